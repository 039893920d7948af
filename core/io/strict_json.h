// SPDX-License-Identifier: MIT
// The program's JSON, read and written with nlohmann/json. Reading goes through its SAX
// interface with a handler that adds what the program's files need beyond RFC 8259:
// duplicate keys refused (each key looked up in a hash set, so linear in the text), nesting
// deeper than maxDepth and text longer than maxBytes refused (hostile input can exhaust
// neither stack nor memory), every number kept as the double nearest its text (std::from_chars,
// so numbers read back exactly) and refused when no finite double is near it. nlohmann
// itself refuses NaN, Infinity, comments, trailing commas, leading zeros, lone surrogates,
// bytes that are not UTF-8 and text after the document. Writing is stable and pretty: 2-space
// indent, object keys in the order they were added, arrays of scalars on one line, numbers
// in the shortest text that reads back to the same double (formatNumber).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace ab::json {

// Keys keep the order of the text (or of insertion), as the preset format lists them.
using Document = nlohmann::ordered_json;

constexpr int maxDepth = 64;
constexpr std::size_t maxBytes = 1 << 20; // 1 MiB

// Parses one JSON document; every number becomes a double. Throws InputError
// "<origin> line L column C: <what>", one line; columns count characters from 1.
Document parse(std::string_view text, const std::string& origin);

// The document as pretty text ending in a newline. Throws std::invalid_argument for a
// non-finite number (JSON has no form for it).
std::string write(const Document& document);

// "an object", "a number", ... for messages.
std::string_view kindName(Document::value_t kind);

} // namespace ab::json
