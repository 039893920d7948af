// SPDX-License-Identifier: MIT
#include "strict_json.h"

#include "../params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <unordered_set>
#include <vector>

namespace ab::json {

namespace {

// A pointer into the text that also records how far the parser has read, so that the
// handler can say where in the text an event happened (nlohmann's SAX events carry no
// position).
class TrackedIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    TrackedIterator(const char* at, const char** readTo) : at_(at), readTo_(readTo) {}

    reference operator*() const { return *at_; }
    TrackedIterator& operator++()
    {
        *readTo_ = ++at_;
        return *this;
    }
    TrackedIterator operator++(int)
    {
        TrackedIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const TrackedIterator& other) const { return at_ == other.at_; }

private:
    const char* at_;
    const char** readTo_;
};

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

// Builds the Document from nlohmann's SAX events and throws InputError at the first thing
// refused, naming where it is.
class Handler {
public:
    using number_integer_t = Document::number_integer_t;
    using number_unsigned_t = Document::number_unsigned_t;
    using number_float_t = Document::number_float_t;
    using string_t = Document::string_t;
    using binary_t = Document::binary_t;

    Handler(std::string_view text, const std::string& origin, const char* const& readTo)
        : text_(text), origin_(origin), readTo_(readTo)
    {
    }

    Document take() { return std::move(root_); }

    bool null() { return put(nullptr); }
    bool boolean(bool b) { return put(b); }
    // nlohmann reads a number as an integer only when it has no fraction or exponent, and
    // as a signed one only when it starts with '-', so a signed 0 was written "-0".
    bool number_integer(number_integer_t x) { return put(x == 0 ? -0.0 : static_cast<double>(x)); }
    // Converting the exact integer rounds to nearest, as from_chars of its digits would.
    bool number_unsigned(number_unsigned_t x) { return put(static_cast<double>(x)); }
    bool number_float(number_float_t, const string_t& token) { return put(exactDouble(token)); }
    bool string(string_t& s) { return put(std::move(s)); }
    bool binary(binary_t&) { return false; } // JSON text has no binary values

    bool start_object(std::size_t)
    {
        open(Document::object());
        return true;
    }
    bool start_array(std::size_t)
    {
        open(Document::array());
        return true;
    }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(string_t& k)
    {
        if (!keys_.back().insert(k).second)
            failAt(keyStart(), "duplicate key '" + printableInput(k) + "'");
        // Appended without ordered_map's linear search for the key: the set above already
        // keeps the keys unique, so an object of n keys is read in O(n).
        Document::object_t& members = stack_.back()->get_ref<Document::object_t&>();
        members.emplace_back(std::move(k), nullptr);
        member_ = &members.back().second;
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const Document::exception& ex)
    {
        if (ex.id == 406) // out_of_range.406: nlohmann's strtod gave an infinity
            failAt(position - lastToken.size(), outOfRange(lastToken));
        // `position` counts the bytes read: a byte the lexer refuses ("...; last read: '...'")
        // was read last; a token the grammar refuses was read whole and is named from its start.
        const std::string what = ex.what();
        const std::size_t last = position == 0 ? 0 : position - 1;
        failAt(what.find("; last read: '") != std::string::npos ? last : tokenStart(last), describe(what, lastToken));
    }

private:
    std::size_t offset() const { return static_cast<std::size_t>(readTo_ - text_.data()); }

    template <typename V> Document* put(V&& value)
    {
        if (stack_.empty()) {
            root_ = Document(std::forward<V>(value));
            return &root_;
        }
        Document& top = *stack_.back();
        if (top.is_array()) {
            Document::array_t& items = top.get_ref<Document::array_t&>();
            items.emplace_back(std::forward<V>(value));
            return &items.back();
        }
        *member_ = Document(std::forward<V>(value));
        return member_;
    }

    // Containers nest only as deep as maxDepth: hostile text cannot grow the stacks.
    void open(Document container)
    {
        if (stack_.size() >= static_cast<std::size_t>(maxDepth))
            failAt(offset() - 1, "nested deeper than " + std::to_string(maxDepth) + " levels"); // at its '[' or '{'
        stack_.push_back(put(std::move(container)));
        keys_.emplace_back();
    }

    bool close()
    {
        stack_.pop_back();
        keys_.pop_back();
        return true;
    }

    // The key's opening quote: the parser has read up to its closing one.
    std::size_t keyStart() const { return stringStart(offset() - 1); }

    // The start of the whole token that ends at byte `last`: a string, a number or a
    // literal (true, false, null); a one-byte token otherwise.
    std::size_t tokenStart(std::size_t last) const
    {
        if (last >= text_.size())
            return last;
        if (text_[last] == '"')
            return stringStart(last);
        std::size_t i = last;
        const auto inNumber = [&](std::size_t k) {
            const char c = text_[k];
            const bool sign = (c == '+' || c == '-') && k > 0 && (text_[k - 1] == 'e' || text_[k - 1] == 'E');
            return isDigit(c) || c == '.' || c == 'e' || c == 'E' || sign;
        };
        if (isDigit(text_[last])) {
            while (i > 0 && inNumber(i - 1))
                --i;
            return i > 0 && text_[i - 1] == '-' ? i - 1 : i;
        }
        while (i > 0 && text_[i - 1] >= 'a' && text_[i - 1] <= 'z')
            --i;
        return i;
    }

    // The opening quote of the string whose closing quote is at `close`: every quote inside
    // a string is escaped (an odd number of backslashes before it).
    std::size_t stringStart(std::size_t close) const
    {
        std::size_t i = close;
        while (i > 0) {
            --i;
            if (text_[i] != '"')
                continue;
            std::size_t slashes = 0;
            while (slashes < i && text_[i - 1 - slashes] == '\\')
                ++slashes;
            if (slashes % 2 == 0)
                return i;
        }
        return i;
    }

    // The double nearest the number's text. from_chars is locale-independent and refuses
    // magnitudes no double holds (non-zero below the smallest subnormal, 4.9e-324, which
    // nlohmann's strtod would round to 0 unnoticed).
    double exactDouble(const string_t& token) const
    {
        std::string text = token;
        for (char& c : text)
            if (!isDigit(c) && c != '-' && c != '+' && c != 'e' && c != 'E')
                c = '.'; // nlohmann's lexer stores the locale's decimal point
        double x = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
        if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) {
            // A number ends in a digit; the parser has read one byte past it unless the text ended.
            const std::size_t stop = offset() > 0 && !isDigit(text_[offset() - 1]) ? offset() - 1 : offset();
            failAt(stop - text.size(), outOfRange(text));
        }
        return x;
    }

    static std::string outOfRange(const std::string& number)
    {
        return "the number " + printableInput(number) + " is outside the range of a double";
    }

    // nlohmann's message without its "[json.exception.parse_error.101] parse error at line
    // 1, column 7: " prefix (the position is given in characters instead), the text it
    // quotes made safe and short.
    static std::string describe(std::string what, const std::string& lastToken)
    {
        if (const auto bracket = what.find("] "); what.starts_with("[json.exception.") && bracket != std::string::npos)
            what.erase(0, bracket + 2);
        if (what.starts_with("parse error"))
            if (const auto colon = what.find(": "); colon != std::string::npos)
                what.erase(0, colon + 2);
        const std::string quoted = "'" + lastToken + "'";
        if (const auto at = what.find(quoted); !lastToken.empty() && at != std::string::npos)
            what.replace(at, quoted.size(), "'" + printableInput(lastToken, 40) + "'");
        return what;
    }

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

    std::string_view text_;
    const std::string& origin_;
    const char* const& readTo_;
    Document root_;
    std::vector<Document*> stack_;                      // the open containers, innermost last
    std::vector<std::unordered_set<std::string>> keys_; // their keys so far (empty for arrays)
    Document* member_ = nullptr;                        // the value of the key read last
};

bool isScalar(const Document& v)
{
    return !v.is_array() && !v.is_object();
}

// JSON's escapes for what may not stand raw in a string (RFC 8259 section 7), by nlohmann;
// a byte that is not UTF-8 is written as U+FFFD.
std::string quoted(const std::string& s)
{
    return Document(s).dump(-1, ' ', false, Document::error_handler_t::replace);
}

std::string numberText(const Document& v)
{
    if (v.is_number_integer())
        return v.is_number_unsigned() ? std::to_string(v.get<std::uint64_t>()) : std::to_string(v.get<std::int64_t>());
    const double x = v.get<double>();
    if (!std::isfinite(x))
        throw std::invalid_argument("JSON has no form for a non-finite number");
    return formatNumber(x); // shortest text that reads back to the same double
}

void writeValue(std::string& out, const Document& v, int indent)
{
    const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
    const std::string outer(static_cast<std::size_t>(indent), ' ');
    switch (v.type()) {
    case Document::value_t::null:
        out += "null";
        return;
    case Document::value_t::boolean:
        out += v.get<bool>() ? "true" : "false";
        return;
    case Document::value_t::number_integer:
    case Document::value_t::number_unsigned:
    case Document::value_t::number_float:
        out += numberText(v);
        return;
    case Document::value_t::string:
        out += quoted(v.get_ref<const std::string&>());
        return;
    case Document::value_t::array: {
        const bool oneLine = std::all_of(v.begin(), v.end(), isScalar);
        out += '[';
        for (std::size_t i = 0; i < v.size(); ++i) {
            out += i == 0 ? "" : ",";
            out += oneLine ? (i == 0 ? "" : " ") : "\n" + inner;
            writeValue(out, v[i], indent + 2);
        }
        out += oneLine || v.empty() ? "]" : "\n" + outer + "]";
        return;
    }
    case Document::value_t::object: {
        bool first = true;
        out += '{';
        for (const auto& [key, value] : v.get_ref<const Document::object_t&>()) {
            out += (first ? "\n" : ",\n") + inner + quoted(key) + ": ";
            writeValue(out, value, indent + 2);
            first = false;
        }
        out += v.empty() ? "}" : "\n" + outer + "}";
        return;
    }
    case Document::value_t::binary:
    case Document::value_t::discarded:
        break;
    }
    throw std::invalid_argument("JSON has no form for a binary or discarded value");
}

} // namespace

Document parse(std::string_view text, const std::string& origin)
{
    if (text.size() > maxBytes)
        throw InputError(origin + " line 1 column 1: the text is longer than " + std::to_string(maxBytes >> 20) +
                         " MiB");
    const char* readTo = text.data();
    Handler handler(text, origin, readTo);
    const char* const end = text.data() + text.size();
    // Strict: the document must end the text. Comments are not JSON and stay refused.
    if (!Document::sax_parse(TrackedIterator(text.data(), &readTo), TrackedIterator(end, &readTo), &handler))
        throw InputError(origin + ": not a JSON document");
    return handler.take();
}

std::string write(const Document& document)
{
    std::string out;
    writeValue(out, document, 0);
    out += '\n';
    return out;
}

std::string_view kindName(Document::value_t kind)
{
    switch (kind) {
    case Document::value_t::null:
        return "null";
    case Document::value_t::boolean:
        return "true or false";
    case Document::value_t::number_integer:
    case Document::value_t::number_unsigned:
    case Document::value_t::number_float:
        return "a number";
    case Document::value_t::string:
        return "a string";
    case Document::value_t::array:
        return "an array";
    case Document::value_t::object:
        return "an object";
    case Document::value_t::binary:
    case Document::value_t::discarded:
        break;
    }
    return "a value";
}

} // namespace ab::json
