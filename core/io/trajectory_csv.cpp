// SPDX-License-Identifier: MIT
#include "trajectory_csv.h"

#include "../params.h"
#include "input_file.h"

#include <array>
#include <charconv>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace ab {

namespace {

constexpr const char* spinColumns = ",wx,wy,wz";

} // namespace

void writeTrajectoryHeader(std::ostream& out, bool spin)
{
    out << "t,ball,x,y,z,vx,vy,vz" << (spin ? spinColumns : "") << "\n";
}

void writeTrajectoryRows(std::ostream& out, const State& s, bool spin)
{
    // Full precision in the shortest form that reads back to the same double (as the
    // window's CSV), through std::to_chars so a locale's decimal comma never reaches the file.
    char line[256];
    auto put = [&](char* at, double x) { return std::to_chars(at, line + sizeof line, x).ptr; };
    for (int i = 0; i < s.size(); ++i) {
        char* at = put(line, s.t);
        *at++ = ',';
        at = std::to_chars(at, line + sizeof line, i).ptr;
        for (int a = 0; a < 3; ++a) {
            *at++ = ',';
            at = put(at, s.p(a, i));
        }
        for (int a = 0; a < 3; ++a) {
            *at++ = ',';
            at = put(at, s.v(a, i));
        }
        for (int a = 0; spin && a < 3; ++a) {
            *at++ = ',';
            at = put(at, s.spins() ? s.w(a, i) : 0.0);
        }
        *at++ = '\n';
        out.write(line, at - line);
    }
}

namespace {

constexpr std::size_t kMaxLine = 1024;       // a row of %.17g numbers is under 200 characters
constexpr std::size_t kMaxBalls = 4'000'000; // many-balls' largest n

// Lines of an --init file, each at most kMaxLine characters: memory stays bounded
// whatever the file holds.
class LineReader {
public:
    LineReader(const ByteSource& read, std::string where) : read_(read), where_(std::move(where)) {}

    bool next(std::string& line)
    {
        line.clear();
        for (;;) {
            if (at_ == end_) {
                end_ = read_(buffer_, sizeof buffer_);
                at_ = 0;
                if (end_ == 0) {
                    if (line.empty())
                        return false;
                    break;
                }
            }
            const char* start = buffer_ + at_;
            const char* nl = static_cast<const char*>(std::memchr(start, '\n', end_ - at_));
            const std::size_t take = nl ? static_cast<std::size_t>(nl - start) : end_ - at_;
            if (line.size() + take > kMaxLine)
                throw InputError(where_ + " line " + std::to_string(number_ + 1) + " is longer than " +
                                 std::to_string(kMaxLine) + " characters");
            line.append(start, take);
            at_ += take + (nl ? 1 : 0);
            if (nl)
                break;
        }
        ++number_;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        return true;
    }
    long number() const { return number_; }

private:
    const ByteSource& read_;
    std::string where_;
    char buffer_[64 * 1024];
    std::size_t at_ = 0, end_ = 0;
    long number_ = 0;
};

std::vector<std::string_view> cellsOf(std::string_view line)
{
    std::vector<std::string_view> cells;
    std::string_view rest = line;
    for (std::size_t comma; (comma = rest.find(',')) != std::string_view::npos; rest.remove_prefix(comma + 1))
        cells.push_back(rest.substr(0, comma));
    cells.push_back(rest);
    return cells;
}

// The number of columns the header names: 8 (t,ball,x,y,z,vx,vy,vz) or 11, with a
// rotating run's wx,wy,wz after them (docs/spin.md).
std::size_t checkHeader(const std::string& line, const std::string& where)
{
    static const char* const names[11] = {"t", "ball", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz"};
    const std::vector<std::string_view> cells = cellsOf(line);
    const std::size_t columns = cells.size() > 8 && cells[8] == "wx" ? 11 : 8;
    for (std::size_t c = 0; c < cells.size(); ++c)
        if (c >= columns || cells[c] != names[c])
            throw InputError(where + ": header column " + std::to_string(c + 1) + " is '" + printableInput(cells[c]) +
                             "', " + (c >= columns ? "one too many" : "not '" + std::string(names[c]) + "'") +
                             " (the header is t,ball,x,y,z,vx,vy,vz, with wx,wy,wz after them for a spinning run)");
    if (cells.size() < columns)
        throw InputError(where + ": the header has " + std::to_string(cells.size()) + " columns, not the " +
                         std::to_string(columns) + " of t,ball,x,y,z,vx,vy,vz" + (columns == 11 ? ",wx,wy,wz" : ""));
    return columns;
}

} // namespace

State readFirstState(const std::filesystem::path& path)
{
    // The size limit is per line and per ball (kMaxLine, kMaxBalls): the first state of a
    // long trajectory is read without reading the rest.
    InputFile file(path, "--init", std::numeric_limits<std::size_t>::max());
    const ByteSource read = [&](char* into, std::size_t size) { return file.read(into, size); };
    return parseFirstState(read, "--init: " + printableInput(path.string()));
}

State parseFirstState(std::string_view text, const std::string& where)
{
    const ByteSource read = [&](char* into, std::size_t size) {
        const std::size_t n = std::min(size, text.size());
        std::memcpy(into, text.data(), n);
        text.remove_prefix(n);
        return n;
    };
    return parseFirstState(read, where);
}

State parseFirstState(const ByteSource& read, const std::string& where)
{
    LineReader lines(read, where);
    std::string line;
    if (!lines.next(line))
        throw InputError(where + " is empty");
    const std::size_t columns = checkHeader(line, where);
    const bool spin = columns == 11;
    std::vector<std::array<double, 10>> rows; // t, x, y, z, vx, vy, vz (, wx, wy, wz)
    while (lines.next(line)) {
        if (line.empty())
            continue;
        const std::vector<std::string_view> cells = cellsOf(line);
        const std::string at = where + " line " + std::to_string(lines.number());
        if (cells.size() != columns)
            throw InputError(at + ": expected " + std::to_string(columns) + " columns, found " +
                             std::to_string(cells.size()));
        std::array<double, 10> row{};
        row[0] = parseReal(cells[0], at + " column t");
        const long long ball = parseInteger(cells[1], at + " column ball");
        static const char* const names[9] = {"x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz"};
        for (std::size_t c = 0; c + 2 < columns; ++c)
            row[c + 1] = parseReal(cells[c + 2], at + " column " + names[c]);
        if (!rows.empty() && row[0] != rows.front()[0])
            break; // the next recorded time: the first state is complete
        if (ball != static_cast<long long>(rows.size()))
            throw InputError(at + ": ball " + std::to_string(ball) + " where ball " + std::to_string(rows.size()) +
                             " was expected (balls in index order)");
        if (rows.size() == kMaxBalls)
            throw InputError(where + ": the first state has more than " + std::to_string(kMaxBalls) +
                             " balls, the most a scene takes");
        rows.push_back(row);
    }
    if (rows.empty())
        throw InputError(where + " has a header but no rows");
    State s;
    s.resize(static_cast<int>(rows.size()));
    s.t = rows.front()[0];
    if (spin)
        s.w.setZero(3, s.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            s.p(a, static_cast<Eigen::Index>(i)) = rows[i][1 + a];
            s.v(a, static_cast<Eigen::Index>(i)) = rows[i][4 + a];
            if (spin)
                s.w(a, static_cast<Eigen::Index>(i)) = rows[i][7 + a];
        }
    return s;
}

} // namespace ab
