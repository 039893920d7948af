// SPDX-License-Identifier: MIT
// The strict JSON reader and the pretty writer: what RFC 8259 accepts and refuses, where
// an error is reported, limits against hostile input, and numbers that read back exactly.
#include "core/io/json.h"
#include "core/params.h"

#include <QtTest>

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

using ab::json::Value;

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
                                        << QByteArray("\"q\\\"b\\\\s/b\\u0008f\\u000cn\\nr\\u000dt\\t\"");
        QTest::newRow("unicode escape") << QByteArray("\"\\u00e9\\u00C5\"") << QByteArray("\"\xC3\xA9\xC3\x85\"");
        QTest::newRow("surrogate pair") << QByteArray("\"\\ud83d\\ude00\"") << QByteArray("\"\xF0\x9F\x98\x80\"");
        QTest::newRow("raw utf-8") << QByteArray("\"Tv\xC3\xA5 bollar \xE2\x82\xAC\"")
                                   << QByteArray("\"Tv\xC3\xA5 bollar \xE2\x82\xAC\"");
        QTest::newRow("byte order mark") << QByteArray("\xEF\xBB\xBF[1]") << QByteArray("[1]");
        QTest::newRow("smallest subnormal") << QByteArray("4.9406564584124654e-324") << QByteArray("5e-324");
        QTest::newRow("largest double") << QByteArray("1.7976931348623157e308")
                                        << QByteArray("1.7976931348623157e+308");
        QTest::newRow("nesting at the limit") << QByteArray::fromStdString(nested(ab::json::maxDepth)) << QByteArray();
    }

    void acceptsWhatTheRfcAllows()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, written);
        const Value v = ab::json::parse(text.toStdString(), "test");
        if (!written.isEmpty())
            QCOMPARE(QByteArray::fromStdString(ab::json::write(v)), written + "\n");
    }

    void refusesWhatTheRfcRefusesAndSaysWhere_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("what");
        QTest::newRow("trailing comma in array") << QByteArray("[1, 2,]") << 1 << 7 << "expected a value, found ']'";
        QTest::newRow("trailing comma in object") << QByteArray("{\"a\": 1,}") << 1 << 9 << "expected a key";
        QTest::newRow("leading zero") << QByteArray("[01]") << 1 << 2 << "leading zero";
        QTest::newRow("negative leading zero") << QByteArray("-012") << 1 << 2 << "leading zero";
        QTest::newRow("NaN") << QByteArray("NaN") << 1 << 1 << "expected a value, found 'N'";
        QTest::newRow("Infinity") << QByteArray("[Infinity]") << 1 << 2 << "expected a value";
        QTest::newRow("negative Infinity") << QByteArray("-Infinity") << 1 << 2 << "expected a digit";
        QTest::newRow("number beyond a double") << QByteArray("[1, 1e400]") << 1 << 5 << "1e400 is outside the range";
        QTest::newRow("number below the smallest double") << QByteArray("1e-400") << 1 << 1 << "outside the range";
        QTest::newRow("plus sign") << QByteArray("+1") << 1 << 1 << "expected a value";
        QTest::newRow("point without digits") << QByteArray("1.") << 1 << 3 << "after the decimal point";
        QTest::newRow("exponent without digits") << QByteArray("2e+") << 1 << 4 << "in the exponent";
        QTest::newRow("hex number") << QByteArray("0x10") << 1 << 2 << "after the end of the document";
        QTest::newRow("lone high surrogate") << QByteArray("\"ab\\ud800\"") << 1 << 4 << "high surrogate \\uD800";
        QTest::newRow("lone low surrogate") << QByteArray("\"\\udc00\"") << 1 << 2 << "low surrogate \\uDC00";
        QTest::newRow("high surrogate before a plain escape")
            << QByteArray("\"\\ud800\\u0041\"") << 1 << 2 << "without a low one";
        QTest::newRow("unterminated string") << QByteArray("[\"abc") << 1 << 2 << "never closed";
        QTest::newRow("control char in string") << QByteArray("\"a\tb\"") << 1 << 3 << "control character";
        QTest::newRow("newline in string") << QByteArray("\"a\nb\"") << 1 << 3 << "control character";
        QTest::newRow("unknown escape") << QByteArray("\"a\\x\"") << 1 << 3 << "unknown escape";
        QTest::newRow("short unicode escape") << QByteArray("\"\\u12g4\"") << 1 << 6 << "four hex digits";
        QTest::newRow("invalid utf-8") << QByteArray("\"a\xFF\"") << 1 << 3 << "not valid UTF-8";
        QTest::newRow("overlong utf-8") << QByteArray("\"\xC0\xAF\"") << 1 << 2 << "not valid UTF-8";
        QTest::newRow("utf-8 encoded surrogate") << QByteArray("\"\xED\xA0\x80\"") << 1 << 2 << "not valid UTF-8";
        QTest::newRow("duplicate keys") << QByteArray("{\"k\": 1, \"k\": 2}") << 1 << 10 << "duplicate key 'k'";
        QTest::newRow("deep nesting") << QByteArray::fromStdString(nested(ab::json::maxDepth + 1)) << 1
                                      << ab::json::maxDepth + 1 << "nested deeper than 64 levels";
        QTest::newRow("single quotes") << QByteArray("{'a': 1}") << 1 << 2 << "expected a key in double quotes";
        QTest::newRow("comment") << QByteArray("// note\n1") << 1 << 1 << "expected a value";
        QTest::newRow("empty text") << QByteArray("") << 1 << 1 << "found the end of the text";
        QTest::newRow("two documents") << QByteArray("1 2") << 1 << 3 << "after the end of the document";
        QTest::newRow("missing colon") << QByteArray("{\"a\" 1}") << 1 << 6 << "expected ':' after a key";
        QTest::newRow("missing comma") << QByteArray("[1 2]") << 1 << 4 << "expected ',' or ']'";
        QTest::newRow("truncated literal") << QByteArray("[tru]") << 1 << 2 << "expected a value";
        QTest::newRow("error on a later line")
            << QByteArray("{\n  \"a\": [1,\n    2,,\n]}") << 3 << 7 << "expected a value, found ','";
        QTest::newRow("column counts characters, not bytes")
            << QByteArray("[\"\xC3\xA9\xE2\x82\xAC\", x]") << 1 << 8 << "expected a value, found 'x'";
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
        const std::string text = ab::json::write(Value::makeArray({Value::makeNumber(x)}));
        const Value back = ab::json::parse(text, "test");
        QCOMPARE(std::bit_cast<std::uint64_t>(back.items.at(0).number), std::bit_cast<std::uint64_t>(x));
    }

    void writerIndentsTwoSpacesAndKeepsTheCallersKeyOrder()
    {
        Value inner = Value::makeObject();
        inner.add("z", Value::makeBool(true)).add("a", Value());
        Value doc = Value::makeObject();
        doc.add("name", Value::makeString("box"))
            .add("p0", Value::makeArray({Value::makeNumber(2), Value::makeNumber(20), Value::makeNumber(2.5)}))
            .add("inner", std::move(inner))
            .add("list", Value::makeArray({Value::makeObject().add("k", Value::makeNumber(0.9))}));
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
        const std::string text = ab::json::write(Value::makeString(s));
        QCOMPARE(ab::json::parse(text, "test").text, s);
        QVERIFY(text.find('\n') == text.size() - 1); // control characters are escaped
    }

    void printableTextIsOneShortLine()
    {
        // Controls escaped so that no terminal sequence passes; quotes left as they are.
        QCOMPARE(ab::json::printable("a\nb\x01\"c\"\x1b[31m"), std::string("a\\nb\\x01\"c\"\\x1b[31m"));
        // A C1 control (U+009B, CSI) and a byte that is not UTF-8.
        QCOMPARE(ab::json::printable("x\xC2\x9By\xFFz"), std::string("x\\u009by\\xffz"));
        // Cut after 80 characters with an ellipsis.
        QCOMPARE(ab::json::printable(std::string(100, 'x')), std::string(80, 'x') + "\xE2\x80\xA6");
        // Characters, not bytes, are counted: never cut inside a character's UTF-8 bytes.
        QCOMPARE(ab::json::printable(std::string(79, 'x') + "\xC3\xA9yz"), std::string(79, 'x') + "\xC3\xA9\xE2\x80\xA6");
    }

    void writerRefusesNonFiniteNumbers()
    {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 ab::json::write(Value::makeNumber(std::numeric_limits<double>::quiet_NaN())));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 ab::json::write(Value::makeNumber(-std::numeric_limits<double>::infinity())));
    }
};

QTEST_GUILESS_MAIN(Json)
#include "test_json.moc"
