// SPDX-License-Identifier: MIT
#include "atomic_file.h"

#include "../params.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <unistd.h>

namespace ab {

namespace {

std::filesystem::path folderOf(const std::filesystem::path& path)
{
    const std::filesystem::path parent = path.parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

} // namespace

void checkWritable(const std::filesystem::path& path)
{
    std::error_code ec;
    if (path.empty())
        throw InputError("output path is empty");
    if (std::filesystem::is_directory(path, ec))
        throw InputError(path.string() + ": is a folder, not a file");
    const std::filesystem::path folder = folderOf(path);
    if (!std::filesystem::is_directory(folder, ec))
        throw InputError(path.string() + ": folder " + folder.string() + " does not exist");
    if (::access(folder.c_str(), W_OK) != 0)
        throw InputError(path.string() + ": folder " + folder.string() + " is not writable");
}

void writeFileAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write)
{
    checkWritable(path);
    std::random_device rd;
    std::string tmpName = path.filename().string();
    tmpName.insert(tmpName.begin(), '.');
    tmpName.append(".tmp").append(std::to_string(rd()));
    const std::filesystem::path tmp = folderOf(path) / tmpName;
    try {
        {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            if (!out)
                throw InputError(path.string() + ": cannot create a file there (" + std::strerror(errno) + ")");
            write(out);
            out.flush();
            if (!out)
                throw InputError(path.string() + ": write failed (disk full?)");
        }
        std::error_code ec;
        std::filesystem::rename(tmp, path, ec);
        if (ec)
            throw InputError(path.string() + ": cannot replace the file (" + ec.message() + ")");
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

} // namespace ab
