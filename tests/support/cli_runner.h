// SPDX-License-Identifier: MIT
// amazeballs-cli run in process, with what it printed and its exit status, and the small
// file helpers the command-line tests share.
#pragma once

#include "app/cli/cli.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace testing {

struct CliResult {
    int status;
    std::string out, err;
};

inline CliResult cli(const std::vector<std::string>& args)
{
    std::ostringstream out, err;
    const int status = ab::cli::run(args, out, err);
    return {status, out.str(), err.str()};
}

inline std::string readFile(const std::filesystem::path& p)
{
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), {}};
}

inline void writeFile(const std::filesystem::path& p, const std::string& text)
{
    std::ofstream(p, std::ios::binary) << text;
}

} // namespace testing
