// SPDX-License-Identifier: MIT
// A small strict JSON reader and writer (RFC 8259) for the program's own files.
// Reading refuses what the RFC refuses (trailing commas, leading zeros, NaN, lone
// surrogates, control characters in strings) and, beyond it, duplicate keys, nesting
// deeper than maxDepth and text longer than maxBytes, so hostile input can neither blow
// the stack nor the memory. Writing is stable and pretty: 2-space indent, object keys in
// the order the caller put them, numbers that read back to the same double.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ab::json {

constexpr int maxDepth = 64;
constexpr std::size_t maxBytes = 1 << 20; // 1 MiB

struct Member;

struct Value {
    enum class Kind { Null, Bool, Number, String, Array, Object };

    Kind kind = Kind::Null;
    bool boolean = false;
    double number = 0.0;
    std::string text;            // String
    std::vector<Value> items;    // Array
    std::vector<Member> members; // Object, in order, keys unique

    static Value makeBool(bool b);
    static Value makeNumber(double x);
    static Value makeString(std::string s);
    static Value makeArray();
    static Value makeArray(std::vector<Value> items);
    static Value makeObject();

    // Object only: appends a member (the caller keeps keys unique); returns *this.
    Value& add(std::string key, Value value);
    // Object only: the member's value, or nullptr.
    const Value* find(std::string_view key) const;

    // Defined where Member is complete (clang with libstdc++ needs it for the members).
    friend bool operator==(const Value& a, const Value& b);
};

struct Member {
    std::string key;
    Value value;

    friend bool operator==(const Member&, const Member&) = default;
};

// Text from a file or a command line made safe to quote in a one-line message: newline,
// tab and return as \n \t \r, other control characters and bytes that are not UTF-8 as
// \xNN (so no terminal escape sequence passes), C1 controls as \u0080..\u009f; cut after
// `max` characters with "…".
std::string printable(std::string_view text, std::size_t max = 80);

// "an object", "a number", ... for messages.
std::string_view kindName(Value::Kind kind);

// Parses one JSON document. Throws InputError "<origin> line L column C: <what>"; columns
// count characters from 1.
Value parse(std::string_view text, const std::string& origin);

// The document as pretty text ending in a newline. Arrays of scalars stay on one line.
// Throws std::invalid_argument for a non-finite number (JSON has no form for it).
std::string write(const Value& value);

} // namespace ab::json
