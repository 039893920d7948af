// SPDX-License-Identifier: MIT
// The strict JSON reader (nlohmann/json's parser with the program's SAX handler) and the
// pretty writer: what RFC 8259 accepts and refuses, where an error is reported, the limits
// against hostile input (duplicate keys found in linear time, depth, size), and numbers
// that read back exactly.
#include "core/io/strict_json.h"
#include "core/params.h"

#include <QtTest>

#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

using ab::json::Document;

namespace {

std::string errorOf(std::string_view text)
{
    try {
        ab::json::parse(text, "test");
    } catch (const ab::InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

std::string nested(int depth)
{
    return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']');
}

} // namespace

class Json : public QObject {
    Q_OBJECT

private slots:
    // Each accepted text is written back in the writer's form; scalars and arrays of
    // scalars are written on one line, so the expected text is short.
    void acceptsWhatTheRfcAllows_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QByteArray>("written");
        QTest::newRow("zero") << QByteArray("0") << QByteArray("0");
        QTest::newRow("negative zero") << QByteArray("-0") << QByteArray("-0");
        QTest::newRow("fraction and exponent") << QByteArray("-12.5e-3") << QByteArray("-0.0125");
        QTest::newRow("capital exponent with plus") << QByteArray("1E+2") << QByteArray("100");
        QTest::newRow("literals") << QByteArray("[true,false,null]") << QByteArray("[true, false, null]");
        QTest::newRow("whitespace everywhere") << QByteArray(" \n\t[ 1 ,\r\n 2 ] \n") << QByteArray("[1, 2]");
        QTest::newRow("empty containers") << QByteArray("[[],{}]") << QByteArray("[\n  [],\n  {}\n]");
        QTest::newRow("simple escapes") << QByteArray("\"q\\\"b\\\\s\\/b\\bf\\fn\\nr\\rt\\t\"")
                                        << QByteArray("\"q\\\"b\\\\s/b\\bf\\fn\\nr\\rt\\t\"");
        QTest::newRow("control escape") << QByteArray("\"\\u0001\\u001F\"") << QByteArray("\"\\u0001\\u001f\"");
        QTest::newRow("unicode escape") << QByteArray("\"\\u00e9\\u00C5\"") << QByteArray("\"\xC3\xA9\xC3\x85\"");
        QTest::newRow("surrogate pair") << QByteArray("\"\\ud83d\\ude00\"") << QByteArray("\"\xF0\x9F\x98\x80\"");
        QTest::newRow("raw utf-8") << QByteArray("\"Tv\xC3\xA5 bollar \xE2\x82\xAC\"")
                                   << QByteArray("\"Tv\xC3\xA5 bollar \xE2\x82\xAC\"");
        QTest::newRow("byte order mark") << QByteArray("\xEF\xBB\xBF[1]") << QByteArray("[1]");
        QTest::newRow("smallest subnormal") << QByteArray("4.9406564584124654e-324") << QByteArray("5e-324");
        QTest::newRow("largest double") << QByteArray("1.7976931348623157e308")
                                        << QByteArray("1.7976931348623157e+308");
        QTest::newRow("integer beyond 2^53 is the nearest double")
            << QByteArray("9007199254740993") << QByteArray("9007199254740992");
        QTest::newRow("integer beyond 2^64 is the nearest double")
            << QByteArray("[36893488147419103232]") << QByteArray("[36893488147419103232]");
        QTest::newRow("negative zero in an array") << QByteArray("[-0, 0, -0.0]") << QByteArray("[-0, 0, -0]");
        QTest::newRow("keys in the text's order")
            << QByteArray("{\"z\":1,\"a\":2}") << QByteArray("{\n  \"z\": 1,\n  \"a\": 2\n}");
        QTest::newRow("nesting at the limit") << QByteArray::fromStdString(nested(ab::json::maxDepth)) << QByteArray();
    }

    void acceptsWhatTheRfcAllows()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, written);
        const Document v = ab::json::parse(text.toStdString(), "test");
        QVERIFY(!v.is_number() || v.is_number_float()); // every number is read as a double
        if (!written.isEmpty())
            QCOMPARE(QByteArray::fromStdString(ab::json::write(v)), written + "\n");
    }

    void refusesWhatTheRfcRefusesAndSaysWhere_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("what");
        QTest::newRow("trailing comma in array") << QByteArray("[1, 2,]") << 1 << 7 << "unexpected ']'";
        QTest::newRow("trailing comma in object")
            << QByteArray("{\"a\": 1,}") << 1 << 9 << "parsing object key - unexpected '}'; expected string literal";
        QTest::newRow("leading zero") << QByteArray("[01]") << 1 << 2 << "unexpected number literal";
        QTest::newRow("negative leading zero") << QByteArray("-012") << 1 << 1 << "expected end of input";
        QTest::newRow("NaN") << QByteArray("NaN") << 1 << 1 << "invalid literal";
        QTest::newRow("Infinity") << QByteArray("[Infinity]") << 1 << 2 << "invalid literal";
        QTest::newRow("negative Infinity") << QByteArray("-Infinity") << 1 << 2 << "expected digit after '-'";
        QTest::newRow("number beyond a double")
            << QByteArray("[1, 1e400]") << 1 << 5 << "the number 1e400 is outside the range of a double";
        QTest::newRow("integer beyond a double")
            << QByteArray("[1" + QByteArray(400, '0') + "]") << 1 << 2 << "outside the range of a double";
        QTest::newRow("number below the smallest double") << QByteArray("1e-400") << 1 << 1 << "outside the range";
        QTest::newRow("number below the smallest double, in an array")
            << QByteArray("[2.5, -1e-400]") << 1 << 7 << "the number -1e-400 is outside";
        QTest::newRow("plus sign") << QByteArray("+1") << 1 << 1 << "invalid literal";
        QTest::newRow("point without digits") << QByteArray("1.") << 1 << 3 << "expected digit after '.'";
        QTest::newRow("exponent without digits") << QByteArray("2e+") << 1 << 4 << "expected digit after exponent sign";
        QTest::newRow("hex number") << QByteArray("0x10") << 1 << 2 << "invalid literal";
        QTest::newRow("lone high surrogate")
            << QByteArray("\"ab\\ud800\"") << 1 << 10 << "surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF";
        QTest::newRow("lone low surrogate")
            << QByteArray("\"\\udc00\"") << 1 << 7 << "surrogate U+DC00..U+DFFF must follow U+D800..U+DBFF";
        QTest::newRow("high surrogate before a plain escape")
            << QByteArray("\"\\ud800\\u0041\"") << 1 << 13 << "must be followed by U+DC00..U+DFFF";
        QTest::newRow("unterminated string") << QByteArray("[\"abc") << 1 << 6 << "missing closing quote";
        QTest::newRow("control char in string") << QByteArray("\"a\tb\"") << 1 << 3 << "control character U+0009";
        QTest::newRow("newline in string") << QByteArray("\"a\nb\"") << 1 << 3 << "control character U+000A";
        QTest::newRow("unknown escape") << QByteArray("\"a\\x\"") << 1 << 4 << "forbidden character after backslash";
        QTest::newRow("short unicode escape") << QByteArray("\"\\u12g4\"") << 1 << 6 << "4 hex digits";
        QTest::newRow("invalid utf-8") << QByteArray("\"a\xFF\"") << 1 << 3 << "ill-formed UTF-8 byte";
        QTest::newRow("overlong utf-8") << QByteArray("\"\xC0\xAF\"") << 1 << 2 << "ill-formed UTF-8 byte";
        QTest::newRow("utf-8 encoded surrogate") << QByteArray("\"\xED\xA0\x80\"") << 1 << 3 << "ill-formed UTF-8";
        QTest::newRow("duplicate keys") << QByteArray("{\"k\": 1, \"k\": 2}") << 1 << 10 << "duplicate key 'k'";
        QTest::newRow("duplicate keys, one escaped")
            << QByteArray("{\"k\\\"\": 1, \"\\u006b\\\"\": 2}") << 1 << 12 << "duplicate key 'k\"'";
        QTest::newRow("duplicate keys in a nested object")
            << QByteArray("{\"a\": {\"k\": 1}, \"b\": {\"k\": 1, \"x\": [], \"k\": 2}}") << 1 << 40
            << "duplicate key 'k'";
        QTest::newRow("deep nesting") << QByteArray::fromStdString(nested(ab::json::maxDepth + 1)) << 1
                                      << ab::json::maxDepth + 1 << "nested deeper than 64 levels";
        QTest::newRow("deep nesting of objects") << QByteArray("{\"a\": ").repeated(ab::json::maxDepth) + "{}" << 1
                                                 << 6 * ab::json::maxDepth + 1 << "nested deeper than 64 levels";
        QTest::newRow("single quotes") << QByteArray("{'a': 1}") << 1 << 2 << "invalid literal";
        QTest::newRow("comment") << QByteArray("// note\n1") << 1 << 1 << "invalid literal";
        QTest::newRow("empty text") << QByteArray("") << 1 << 1 << "unexpected end of input";
        QTest::newRow("only whitespace") << QByteArray(" \n ") << 2 << 2 << "unexpected end of input";
        QTest::newRow("truncated object") << QByteArray("{\"a\": [1, 2") << 1 << 12 << "unexpected end of input";
        QTest::newRow("two documents") << QByteArray("1 2") << 1 << 3 << "expected end of input";
        QTest::newRow("trailing garbage") << QByteArray("{} x") << 1 << 4 << "invalid literal";
        QTest::newRow("missing colon") << QByteArray("{\"a\" 1}") << 1 << 6 << "expected ':'";
        QTest::newRow("missing comma") << QByteArray("[1 2]") << 1 << 4 << "expected ']'";
        QTest::newRow("missing comma before a string") << QByteArray("[1 \"two\"]") << 1 << 4 << "string literal";
        QTest::newRow("truncated literal") << QByteArray("[tru]") << 1 << 5 << "invalid literal";
        QTest::newRow("byte order mark after whitespace")
            << QByteArray(" \xEF\xBB\xBF[1]") << 1 << 2 << "invalid literal";
        QTest::newRow("broken byte order mark") << QByteArray("\xEF\xBB[1]") << 1 << 2 << "invalid BOM";
        QTest::newRow("error on a later line")
            << QByteArray("{\n  \"a\": [1,\n    2,,\n]}") << 3 << 7 << "unexpected ','";
        QTest::newRow("column counts characters, not bytes")
            << QByteArray("[\"\xC3\xA9\xE2\x82\xAC\", x]") << 1 << 8 << "invalid literal";
    }

    void refusesWhatTheRfcRefusesAndSaysWhere()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QString, what);
        const QString message = QString::fromStdString(errorOf(text.toStdString()));
        const QString where = QString("test line %1 column %2: ").arg(line).arg(column);
        QVERIFY2(message.startsWith(where), qPrintable(message));
        QVERIFY2(message.contains(what), qPrintable(message));
        QVERIFY2(!message.contains('\n') && !message.contains("json.exception"), qPrintable(message));
    }

    // What the text quotes is shown made safe and cut: no control byte, no 1 MB echo.
    void quotedTextIsSafeAndShort()
    {
        const std::string escape = errorOf("[\"\x1b[31m\"]"); // nlohmann names it U+001B
        QVERIFY2(escape.find('\x1b') == std::string::npos, escape.c_str());
        const std::string stray = errorOf("[\"\x7f\xC2\x9b\xFF\"]"); // DEL and a C1 control are JSON, 0xFF not
        QVERIFY2(stray.find("ill-formed UTF-8") != std::string::npos, stray.c_str());
        QVERIFY2(stray.find("last read: '\"\\x7f\\u009b\\xff'") != std::string::npos, stray.c_str());
        std::string unclosed = "[\"";
        unclosed.append(500'000, 'x');
        const std::string open = errorOf(unclosed);
        QVERIFY2(open.find("missing closing quote") != std::string::npos, open.c_str());
        QVERIFY2(open.size() < 200, open.c_str());
        std::string digits = "1";
        digits.append(900'000, '0');
        const std::string big = errorOf(digits);
        QVERIFY2(big.find("outside the range of a double") != std::string::npos && big.size() < 200, big.c_str());
    }

    // The handler keeps a hash set of each open object's keys, so 70,000 distinct keys, and
    // a duplicate of one of them at the end, are read in linear time; a search of the keys
    // read so far would take 70,000^2 / 2 = 2.5e9 string comparisons. Twenty times the keys take
    // about twenty times as long to read (four hundred times with a search): the ratio of the two
    // reading times, each the best of five, holds however loaded or instrumented the
    // machine is, where a bound on seconds does not.
    void manyKeysAreReadInLinearTime()
    {
        const auto objectOf = [](int count) {
            std::string keys;
            for (int i = 0; i < count; ++i)
                keys += (i == 0 ? "" : ", ") + std::string("\"k") + std::to_string(i) + "\": 0";
            return keys;
        };
        const std::string keys = objectOf(70000), fewer = objectOf(3500);
        const Document doc = ab::json::parse("{" + keys + "}", "test");
        QCOMPARE(doc.size(), std::size_t(70000));
        QCOMPARE(doc.begin().key(), std::string("k0")); // the text's order
        QCOMPARE((--doc.end()).key(), std::string("k69999"));
        const std::string error = errorOf("{" + keys + ", \"k5\": 1}");
        QVERIFY2(QString::fromStdString(error).contains(QRegularExpression("line 1 column \\d+: duplicate key 'k5'$")),
                 error.c_str());
        const auto secondsToRead = [](const std::string& text) {
            double best = std::numeric_limits<double>::infinity();
            for (int k = 0; k < 5; ++k) {
                const auto start = std::chrono::steady_clock::now();
                errorOf("{" + text + ", \"k5\": 1}");
                best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            return best;
        };
        const double ratio = secondsToRead(keys) / secondsToRead(fewer);
        QVERIFY2(ratio < 120.0, qPrintable(QString("twenty times the keys took %1 times as long").arg(ratio)));
    }

    void hostileNestingIsRefusedBeforeTheStackGrows()
    {
        // A million open brackets: refused at depth 65, so the recursion stays shallow.
        const std::string text(1'000'000, '[');
        QVERIFY(QString::fromStdString(errorOf(text)).contains("nested deeper than 64 levels"));
    }

    void textLongerThanTheLimitIsRefusedUnread()
    {
        std::string text = "[" + std::string(ab::json::maxBytes, ' ') + "]";
        QVERIFY(QString::fromStdString(errorOf(text)).contains("longer than 1 MiB"));
        text.resize(ab::json::maxBytes - 1);
        text.back() = ']';
        QCOMPARE(errorOf(text), std::string("(accepted)"));
    }

    void numbersReadBackToTheSameDouble_data()
    {
        QTest::addColumn<double>("x");
        QTest::newRow("0.1") << 0.1;
        QTest::newRow("1/3") << 1.0 / 3.0;
        QTest::newRow("2/3") << 2.0 / 3.0;
        QTest::newRow("0.1 + 0.2") << 0.1 + 0.2;
        QTest::newRow("1e-300") << 1e-300;
        QTest::newRow("subnormal") << 2.5e-310;
        QTest::newRow("smallest subnormal") << std::numeric_limits<double>::denorm_min();
        QTest::newRow("largest") << std::numeric_limits<double>::max();
        QTest::newRow("2^53 + 2") << 9007199254740994.0;
        QTest::newRow("negative zero") << -0.0;
        QTest::newRow("9.82/1000") << 9.82 / 1000.0;
        QTest::newRow("pi") << std::numbers::pi;
    }

    void numbersReadBackToTheSameDouble()
    {
        QFETCH(double, x);
        const std::string text = ab::json::write(Document::array({x}));
        const Document back = ab::json::parse(text, "test");
        QCOMPARE(std::bit_cast<std::uint64_t>(back.at(0).get<double>()), std::bit_cast<std::uint64_t>(x));
    }

    void writerIndentsTwoSpacesAndKeepsTheCallersKeyOrder()
    {
        Document inner = Document::object();
        inner["z"] = true;
        inner["a"] = nullptr;
        Document doc = Document::object();
        doc["name"] = "box";
        doc["p0"] = Document::array({2.0, 20.0, 2.5});
        doc["inner"] = std::move(inner);
        doc["list"] = Document::array({Document::object({{"k", 0.9}})});
        QCOMPARE(ab::json::write(doc), std::string("{\n"
                                                   "  \"name\": \"box\",\n"
                                                   "  \"p0\": [2, 20, 2.5],\n"
                                                   "  \"inner\": {\n"
                                                   "    \"z\": true,\n"
                                                   "    \"a\": null\n"
                                                   "  },\n"
                                                   "  \"list\": [\n"
                                                   "    {\n"
                                                   "      \"k\": 0.9\n"
                                                   "    }\n"
                                                   "  ]\n"
                                                   "}\n"));
    }

    void stringsWithEscapesAndUnicodeRoundTrip()
    {
        const std::string s = "quote \" backslash \\ slash / tab \t newline \n bell \x07 del \x7F "
                              "\xC3\xA5\xC3\xA4\xC3\xB6 \xF0\x9F\x8E\xB1";
        const std::string text = ab::json::write(Document(s));
        QCOMPARE(ab::json::parse(text, "test").get<std::string>(), s);
        QVERIFY(text.find('\n') == text.size() - 1); // control characters are escaped
    }

    void writerRefusesNonFiniteNumbers()
    {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 ab::json::write(Document(std::numeric_limits<double>::quiet_NaN())));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 ab::json::write(Document::array({-std::numeric_limits<double>::infinity()})));
    }
};

QTEST_GUILESS_MAIN(Json)
#include "test_json.moc"
