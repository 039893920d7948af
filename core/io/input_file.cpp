// SPDX-License-Identifier: MIT
#include "input_file.h"

#include "../params.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ab {

std::string fileKindName(unsigned mode)
{
    switch (mode & S_IFMT) {
    case S_IFDIR:
        return "a folder";
    case S_IFIFO:
        return "a FIFO (named pipe)";
    case S_IFCHR:
        return "a character device";
    case S_IFBLK:
        return "a block device";
    case S_IFSOCK:
        return "a socket";
    case S_IFREG:
        return "a regular file";
    default:
        return "not a regular file";
    }
}

namespace {

std::string mebibytes(std::size_t bytes)
{
    return bytes >= (1u << 20) ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}

} // namespace

InputFile::InputFile(const std::filesystem::path& path, const std::string& what, std::size_t maxBytes) : what_(what)
{
    if (path.empty())
        throw InputError(what + ": no file name given");
    // O_NONBLOCK: opening a FIFO does not wait for a writer; the kind is checked next.
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    const std::string name = printableInput(path.string());
    if (fd_ < 0) {
        const int error = errno;
        if (error == ENOENT)
            throw InputError(what + ": " + name + ": no such file");
        throw InputError(what + ": " + name + ": cannot read it (" + std::strerror(error) + ")");
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0) {
        const int error = errno;
        ::close(fd_);
        throw InputError(what + ": " + name + ": cannot read it (" + std::strerror(error) + ")");
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd_);
        throw InputError(what + ": " + name + " is " + fileKindName(st.st_mode) + ", not a file");
    }
    if (static_cast<unsigned long long>(st.st_size) > maxBytes) {
        ::close(fd_);
        throw InputError(what + ": " + name + " is larger than " + mebibytes(maxBytes));
    }
    size_ = static_cast<std::size_t>(st.st_size);
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
}

InputFile::~InputFile()
{
    ::close(fd_);
}

std::size_t InputFile::read(char* into, std::size_t size)
{
    for (;;) {
        const ssize_t n = ::read(fd_, into, size);
        if (n >= 0)
            return static_cast<std::size_t>(n);
        if (errno != EINTR)
            throw InputError(what_ + ": cannot read the file (" + std::strerror(errno) + ")");
    }
}

std::string readInputFile(const std::filesystem::path& path, const std::string& what, std::size_t maxBytes)
{
    InputFile file(path, what, maxBytes);
    std::string text;
    text.resize(file.size() + 1); // one more: a file that grew since is noticed
    std::size_t have = 0;
    for (std::size_t n; (n = file.read(text.data() + have, text.size() - have)) > 0;) {
        have += n;
        if (have > maxBytes)
            throw InputError(what + ": " + printableInput(path.string()) + " is larger than " + mebibytes(maxBytes));
        if (have == text.size())
            text.resize(std::min(text.size() * 2, maxBytes + 1));
    }
    text.resize(have);
    return text;
}

} // namespace ab
