// SPDX-License-Identifier: MIT
#include "trajectory_csv.h"

#include "../params.h"

#include <array>
#include <charconv>
#include <fstream>
#include <string>
#include <vector>

namespace ab {

void writeTrajectoryHeader(std::ostream& out)
{
    out << "t,ball,x,y,z,vx,vy,vz\n";
}

void writeTrajectoryRows(std::ostream& out, const State& s)
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
    std::vector<std::array<double, 7>> rows; // t, x, y, z, vx, vy, vz
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
        if (cells.size() < 8)
            throw InputError(where + ": expected 8 columns, found " + std::to_string(cells.size()));
        std::array<double, 7> row{};
        row[0] = parseReal(cells[0], where + " column t");
        const long long ball = parseInteger(cells[1], where + " column ball");
        static const char* const columns[6] = {"x", "y", "z", "vx", "vy", "vz"};
        for (int c = 0; c < 6; ++c)
            row[c + 1] = parseReal(cells[c + 2], where + " column " + columns[c]);
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
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            s.p(a, static_cast<Eigen::Index>(i)) = rows[i][1 + a];
            s.v(a, static_cast<Eigen::Index>(i)) = rows[i][4 + a];
        }
    return s;
}

} // namespace ab
