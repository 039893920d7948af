// SPDX-License-Identifier: MIT
#include "trajectory_csv.h"

#include "../params.h"

#include <array>
#include <charconv>
#include <fstream>
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
    // "%.17g" as the contract asks, through std::to_chars so a locale's decimal comma
    // never reaches the file.
    char line[256];
    auto put = [&](char* at, double x) {
        return std::to_chars(at, line + sizeof line, x, std::chars_format::general, 17).ptr;
    };
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

State readFirstState(const std::filesystem::path& path)
{
    std::ifstream in(path);
    const std::string name = path.string();
    if (!in)
        throw InputError("--init: cannot read " + name);
    std::string line;
    if (!std::getline(in, line))
        throw InputError("--init: " + name + " is empty");
    if (!line.empty() && line.back() == '\r')
        line.pop_back();
    if (line.rfind("t,ball,x,y,z,vx,vy,vz", 0) != 0)
        throw InputError("--init: " + name + " does not start with the header t,ball,x,y,z,vx,vy,vz");
    const bool spin =
        line.compare(21, 9, spinColumns) == 0 && (line.size() == 30 || line[30] == ','); // wx,wy,wz right after vz
    const std::size_t columns = spin ? 11 : 8;
    std::vector<std::array<double, 10>> rows; // t, x, y, z, vx, vy, vz (, wx, wy, wz)
    long lineNo = 1;
    while (std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.empty())
            continue;
        std::vector<std::string_view> cells;
        std::string_view rest = line;
        for (std::size_t comma; (comma = rest.find(',')) != std::string_view::npos; rest.remove_prefix(comma + 1))
            cells.push_back(rest.substr(0, comma));
        cells.push_back(rest);
        const std::string where = "--init: " + name + " line " + std::to_string(lineNo);
        if (cells.size() < columns)
            throw InputError(where + ": expected " + std::to_string(columns) + " columns, found " +
                             std::to_string(cells.size()));
        std::array<double, 10> row{};
        row[0] = parseReal(cells[0], where + " column t");
        const long long ball = parseInteger(cells[1], where + " column ball");
        static const char* const names[9] = {"x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz"};
        for (std::size_t c = 0; c + 2 < columns; ++c)
            row[c + 1] = parseReal(cells[c + 2], where + " column " + names[c]);
        if (!rows.empty() && row[0] != rows.front()[0])
            break; // the next recorded time: the first state is complete
        if (ball != static_cast<long long>(rows.size()))
            throw InputError(where + ": ball " + std::to_string(ball) + " where ball " + std::to_string(rows.size()) +
                             " was expected (balls in index order)");
        rows.push_back(row);
    }
    if (rows.empty())
        throw InputError("--init: " + name + " has a header but no rows");
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
