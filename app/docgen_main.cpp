// SPDX-License-Identifier: MIT
// amazeballs-docgen OUTDIR VERSION DATE: writes the man pages and shell completions
// (cli/docgen.h) into OUTDIR/man, OUTDIR/bash and OUTDIR/zsh. Run by the build.
#include "cli/docgen.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

namespace {

bool write(const std::filesystem::path& path, const std::function<void(std::ostream&)>& fill)
{
    std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    fill(out);
    out.close();
    if (!out) {
        std::fprintf(stderr, "amazeballs-docgen: %s: not written\n", path.c_str());
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: amazeballs-docgen OUTDIR VERSION DATE\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    const ab::cli::PageInfo info{argv[2], argv[3]};
    using namespace ab::cli;
    const bool ok = write(dir / "man/amazeballs-cli.1", [&](std::ostream& o) { writeCliManPage(o, info); }) &&
                    write(dir / "man/amazeballs.1", [&](std::ostream& o) { writeWindowManPage(o, info); }) &&
                    write(dir / "bash/amazeballs-cli", writeCliBashCompletion) &&
                    write(dir / "bash/amazeballs", writeWindowBashCompletion) &&
                    write(dir / "zsh/_amazeballs-cli", writeCliZshCompletion) &&
                    write(dir / "zsh/_amazeballs", writeWindowZshCompletion);
    return ok ? 0 : 1;
}
