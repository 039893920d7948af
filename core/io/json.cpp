// SPDX-License-Identifier: MIT
#include "json.h"

#include "../params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_set>

namespace ab::json {

Value Value::makeBool(bool b)
{
    Value v;
    v.kind = Kind::Bool;
    v.boolean = b;
    return v;
}

Value Value::makeNumber(double x)
{
    Value v;
    v.kind = Kind::Number;
    v.number = x;
    return v;
}

Value Value::makeString(std::string s)
{
    Value v;
    v.kind = Kind::String;
    v.text = std::move(s);
    return v;
}

Value Value::makeArray(std::vector<Value> items)
{
    Value v;
    v.kind = Kind::Array;
    v.items = std::move(items);
    return v;
}

Value Value::makeArray()
{
    return makeArray(std::vector<Value>());
}

bool operator==(const Value& a, const Value& b)
{
    return a.kind == b.kind && a.boolean == b.boolean && a.number == b.number && a.text == b.text &&
           a.items == b.items && a.members == b.members;
}

Value Value::makeObject()
{
    Value v;
    v.kind = Kind::Object;
    return v;
}

Value& Value::add(std::string key, Value value)
{
    members.push_back({std::move(key), std::move(value)});
    return *this;
}

const Value* Value::find(std::string_view key) const
{
    for (const Member& m : members)
        if (m.key == key)
            return &m.value;
    return nullptr;
}

std::string_view kindName(Value::Kind kind)
{
    switch (kind) {
    case Value::Kind::Null:
        return "null";
    case Value::Kind::Bool:
        return "true or false";
    case Value::Kind::Number:
        return "a number";
    case Value::Kind::String:
        return "a string";
    case Value::Kind::Array:
        return "an array";
    case Value::Kind::Object:
        return "an object";
    }
    return "a value";
}

namespace {

// Recursive descent over the grammar of RFC 8259; `pos_` is a byte offset into the text.
class Parser {
public:
    Parser(std::string_view text, const std::string& origin) : text_(text), origin_(origin) {}

    Value document()
    {
        if (text_.size() > maxBytes)
            fail("the text is longer than " + std::to_string(maxBytes >> 20) + " MiB");
        // A UTF-8 byte order mark is tolerated (RFC 8259 8.1 lets a parser ignore it).
        if (text_.substr(0, 3) == "\xEF\xBB\xBF")
            pos_ = 3;
        Value v = value(0);
        skipSpace();
        if (pos_ < text_.size())
            fail("unexpected text after the end of the document");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& what) const { failAt(pos_, what); }

    [[noreturn]] void failAt(std::size_t at, const std::string& what) const
    {
        int line = 1, column = 1;
        for (std::size_t i = 0; i < at && i < text_.size(); ++i) {
            if (text_[i] == '\n') {
                ++line;
                column = 1;
            } else if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) {
                ++column; // a UTF-8 continuation byte is not a new character
            }
        }
        throw InputError(origin_ + " line " + std::to_string(line) + " column " + std::to_string(column) + ": " + what);
    }

    bool atEnd() const { return pos_ >= text_.size(); }
    char peek() const { return atEnd() ? '\0' : text_[pos_]; }

    void skipSpace()
    {
        while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r'))
            ++pos_;
    }

    std::string describeHere() const
    {
        if (atEnd())
            return "the end of the text";
        const unsigned char c = static_cast<unsigned char>(peek());
        if (c < 0x20 || c >= 0x7F)
            return "a control or non-ASCII character";
        return std::string("'") + peek() + "'";
    }

    void expect(char c, const char* context)
    {
        skipSpace();
        if (peek() != c)
            fail(std::string("expected '") + c + "' " + context + ", found " + describeHere());
        ++pos_;
    }

    Value value(int depth)
    {
        skipSpace();
        switch (peek()) {
        case '{':
            return object(depth + 1);
        case '[':
            return array(depth + 1);
        case '"':
            return Value::makeString(string());
        case 't':
            return literal("true", Value::makeBool(true));
        case 'f':
            return literal("false", Value::makeBool(false));
        case 'n':
            return literal("null", Value());
        default:
            if (peek() == '-' || (peek() >= '0' && peek() <= '9'))
                return number();
            fail("expected a value, found " + describeHere());
        }
    }

    Value literal(std::string_view word, Value v)
    {
        if (text_.substr(pos_, word.size()) != word)
            fail("expected a value, found " + describeHere());
        pos_ += word.size();
        return v;
    }

    void enter(int depth) const
    {
        if (depth > maxDepth)
            fail("nested deeper than " + std::to_string(maxDepth) + " levels");
    }

    Value object(int depth)
    {
        enter(depth);
        ++pos_; // '{'
        Value v = Value::makeObject();
        std::unordered_set<std::string> keys; // duplicates found in O(1) a key, not O(members)
        skipSpace();
        if (peek() == '}') {
            ++pos_;
            return v;
        }
        for (;;) {
            skipSpace();
            if (peek() != '"')
                fail("expected a key in double quotes, found " + describeHere());
            const std::size_t keyAt = pos_;
            std::string key = string();
            if (!keys.insert(key).second)
                failAt(keyAt, "duplicate key '" + printable(key) + "'");
            expect(':', "after a key");
            v.add(std::move(key), value(depth));
            skipSpace();
            if (peek() == '}') {
                ++pos_;
                return v;
            }
            expect(',', "or '}' after a member");
        }
    }

    Value array(int depth)
    {
        enter(depth);
        ++pos_; // '['
        Value v = Value::makeArray();
        skipSpace();
        if (peek() == ']') {
            ++pos_;
            return v;
        }
        for (;;) {
            v.items.push_back(value(depth));
            skipSpace();
            if (peek() == ']') {
                ++pos_;
                return v;
            }
            expect(',', "or ']' after an array item");
        }
    }

    // number = [ "-" ] ( "0" / 1-9 *DIGIT ) [ "." 1*DIGIT ] [ ( "e" / "E" ) [ "-" / "+" ] 1*DIGIT ]
    Value number()
    {
        const std::size_t start = pos_;
        auto digits = [&] {
            const std::size_t from = pos_;
            while (peek() >= '0' && peek() <= '9')
                ++pos_;
            return pos_ - from;
        };
        if (peek() == '-')
            ++pos_;
        if (peek() == '0' && pos_ + 1 < text_.size() && text_[pos_ + 1] >= '0' && text_[pos_ + 1] <= '9')
            fail("a number may not have a leading zero");
        if (digits() == 0)
            fail("expected a digit, found " + describeHere());
        if (peek() == '.') {
            ++pos_;
            if (digits() == 0)
                fail("expected a digit after the decimal point, found " + describeHere());
        }
        if (peek() == 'e' || peek() == 'E') {
            ++pos_;
            if (peek() == '+' || peek() == '-')
                ++pos_;
            if (digits() == 0)
                fail("expected a digit in the exponent, found " + describeHere());
        }
        // from_chars is locale-independent; it refuses magnitudes a double cannot hold
        // (above about 1.8e308, and non-zero below the smallest subnormal, 4.9e-324).
        double x = 0.0;
        const auto [end, ec] = std::from_chars(text_.data() + start, text_.data() + pos_, x);
        if (ec != std::errc() || end != text_.data() + pos_ || !std::isfinite(x))
            failAt(start,
                   "the number " + printable(text_.substr(start, pos_ - start)) + " is outside the range of a double");
        return Value::makeNumber(x);
    }

    unsigned hex4()
    {
        unsigned code = 0;
        for (int i = 0; i < 4; ++i, ++pos_) {
            const char c = peek();
            const int d = c >= '0' && c <= '9'   ? c - '0'
                          : c >= 'a' && c <= 'f' ? c - 'a' + 10
                          : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                 : -1;
            if (d < 0)
                fail("expected four hex digits after \\u");
            code = code * 16 + static_cast<unsigned>(d);
        }
        return code;
    }

    // \uXXXX, or a surrogate pair \uD8xx\uDCxx for a code point above U+FFFF.
    unsigned escapedCodePoint()
    {
        const std::size_t at = pos_ - 2;
        const unsigned first = hex4();
        if (first >= 0xDC00 && first <= 0xDFFF)
            failAt(at, "a low surrogate \\u" + hexText(first) + " without a high one before it");
        if (first < 0xD800 || first > 0xDBFF)
            return first;
        if (text_.substr(pos_, 2) != "\\u")
            failAt(at, "a high surrogate \\u" + hexText(first) + " without a low one after it");
        pos_ += 2;
        const unsigned second = hex4();
        if (second < 0xDC00 || second > 0xDFFF)
            failAt(at, "a high surrogate \\u" + hexText(first) + " without a low one after it");
        return 0x10000 + ((first - 0xD800) << 10) + (second - 0xDC00);
    }

    static std::string hexText(unsigned code)
    {
        char buf[8];
        std::snprintf(buf, sizeof buf, "%04X", code);
        return buf;
    }

    static void appendUtf8(std::string& out, unsigned cp)
    {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    // Length of the well-formed UTF-8 sequence at pos_ (Unicode table 3-7), 0 if none.
    std::size_t utf8Length() const
    {
        auto byte = [&](std::size_t i) {
            return pos_ + i < text_.size() ? static_cast<unsigned char>(text_[pos_ + i]) : 0u;
        };
        const unsigned b0 = byte(0);
        auto cont = [&](std::size_t i, unsigned lo = 0x80, unsigned hi = 0xBF) {
            return byte(i) >= lo && byte(i) <= hi;
        };
        if (b0 >= 0xC2 && b0 <= 0xDF)
            return cont(1) ? 2 : 0;
        if (b0 >= 0xE0 && b0 <= 0xEF) {
            const bool second = b0 == 0xE0 ? cont(1, 0xA0) : b0 == 0xED ? cont(1, 0x80, 0x9F) : cont(1);
            return second && cont(2) ? 3 : 0;
        }
        if (b0 >= 0xF0 && b0 <= 0xF4) {
            const bool second = b0 == 0xF0 ? cont(1, 0x90) : b0 == 0xF4 ? cont(1, 0x80, 0x8F) : cont(1);
            return second && cont(2) && cont(3) ? 4 : 0;
        }
        return 0;
    }

    std::string string()
    {
        const std::size_t start = pos_;
        ++pos_; // opening quote
        std::string out;
        for (;;) {
            if (atEnd())
                failAt(start, "a string that is never closed");
            const unsigned char c = static_cast<unsigned char>(peek());
            if (c == '"') {
                ++pos_;
                return out;
            }
            if (c < 0x20)
                fail("a control character in a string (write it as an escape such as \\n)");
            if (c >= 0x80) {
                const std::size_t n = utf8Length();
                if (n == 0)
                    fail("bytes that are not valid UTF-8");
                out.append(text_.substr(pos_, n));
                pos_ += n;
                continue;
            }
            ++pos_;
            if (c != '\\') {
                out += static_cast<char>(c);
                continue;
            }
            // The escapes of RFC 8259 section 7: \" \\ \/ \b \f \n \r \t and \uXXXX.
            constexpr std::string_view escapes = "\"\\/bfnrt", meanings = "\"\\/\b\f\n\r\t";
            const char e = peek();
            ++pos_;
            if (e == 'u')
                appendUtf8(out, escapedCodePoint());
            else if (const auto i = escapes.find(e); i != std::string_view::npos)
                out += meanings[i];
            else
                failAt(pos_ - 2, "an unknown escape in a string");
        }
    }

    std::string_view text_;
    const std::string& origin_;
    std::size_t pos_ = 0;
};

// JSON's escapes for what may not stand raw in a string (RFC 8259 section 7).
void appendEscaped(std::string& out, std::string_view s)
{
    for (const char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
            out += buf;
        } else {
            out += c;
        }
    }
}

void writeString(std::string& out, std::string_view s)
{
    out += '"';
    appendEscaped(out, s);
    out += '"';
}

bool isScalar(const Value& v)
{
    return v.kind != Value::Kind::Array && v.kind != Value::Kind::Object;
}

void writeValue(std::string& out, const Value& v, int indent)
{
    const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
    const std::string outer(static_cast<std::size_t>(indent), ' ');
    switch (v.kind) {
    case Value::Kind::Null:
        out += "null";
        return;
    case Value::Kind::Bool:
        out += v.boolean ? "true" : "false";
        return;
    case Value::Kind::Number:
        if (!std::isfinite(v.number))
            throw std::invalid_argument("JSON has no form for a non-finite number");
        out += formatNumber(v.number); // shortest text that reads back to the same double
        return;
    case Value::Kind::String:
        writeString(out, v.text);
        return;
    case Value::Kind::Array: {
        const bool oneLine = std::all_of(v.items.begin(), v.items.end(), isScalar);
        out += '[';
        for (std::size_t i = 0; i < v.items.size(); ++i) {
            out += i == 0 ? "" : ",";
            out += oneLine ? (i == 0 ? "" : " ") : "\n" + inner;
            writeValue(out, v.items[i], indent + 2);
        }
        out += oneLine || v.items.empty() ? "]" : "\n" + outer + "]";
        return;
    }
    case Value::Kind::Object:
        out += '{';
        for (std::size_t i = 0; i < v.members.size(); ++i) {
            out += (i == 0 ? "\n" : ",\n") + inner;
            writeString(out, v.members[i].key);
            out += ": ";
            writeValue(out, v.members[i].value, indent + 2);
        }
        out += v.members.empty() ? "}" : "\n" + outer + "}";
        return;
    }
}

} // namespace

namespace {

// The length of the valid UTF-8 sequence at text[i], or 0 when the byte starts none.
std::size_t utf8Length(std::string_view text, std::size_t i)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b = byte(i);
    const std::size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > text.size())
        return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((byte(i + k) & 0xC0) != 0x80)
            return 0;
    if (n == 2 && b < 0xC2)
        return 0; // overlong
    return n;
}

} // namespace

std::string printable(std::string_view text, std::size_t max)
{
    std::string out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < text.size();) {
        if (chars == max)
            return out + "\xE2\x80\xA6"; // "…", the cut
        ++chars;
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t n = utf8Length(text, i);
        char buf[8];
        if (c == '\n' || c == '\t' || c == '\r') {
            out += c == '\n' ? "\\n" : c == '\t' ? "\\t" : "\\r";
        } else if (n == 0 || c < 0x20 || c == 0x7F) {
            std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(c)); // a control or a stray byte
            out += buf;
        } else if (n == 2 && c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0) {
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(text[i + 1]) & 0xFFu); // C1 control
            out += buf;
        } else {
            out.append(text.substr(i, n));
        }
        i += n == 0 ? 1 : n;
    }
    return out;
}

Value parse(std::string_view text, const std::string& origin)
{
    return Parser(text, origin).document();
}

std::string write(const Value& value)
{
    std::string out;
    writeValue(out, value, 0);
    out += '\n';
    return out;
}

} // namespace ab::json
