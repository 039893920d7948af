// SPDX-License-Identifier: MIT
#include "fd_stream.h"

#include "atomic_file.h"

#include "../interrupt.h"

#include <cerrno>
#include <cstring>
#include <unistd.h>

namespace ab {

FdStreamBuf::FdStreamBuf(int fd, std::string name, std::string suffix)
    : fd_(fd), name_(std::move(name)), suffix_(std::move(suffix)), buffer_(64 * 1024)
{
    setp(buffer_.data(), buffer_.data() + buffer_.size());
}

void FdStreamBuf::writeAll(const char* data, std::size_t size)
{
    while (size > 0) {
        const ssize_t n = ::write(fd_, data, size);
        if (n < 0 && errno == EINTR) {
            throwIfInterruptRequested();
            continue;
        }
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC; // write() of 0 bytes to a file: no room
            discard();
            throw OutputError(writeFailure(name_, error) + suffix_);
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
}

void FdStreamBuf::flushNow()
{
    const std::size_t size = static_cast<std::size_t>(pptr() - pbase());
    discard();
    writeAll(buffer_.data(), size);
}

FdStreamBuf::int_type FdStreamBuf::overflow(int_type c)
{
    flushNow();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
        *pptr() = traits_type::to_char_type(c);
        pbump(1);
    }
    return traits_type::not_eof(c);
}

std::streamsize FdStreamBuf::xsputn(const char* s, std::streamsize n)
{
    const std::streamsize room = epptr() - pptr();
    if (n <= room) {
        std::memcpy(pptr(), s, static_cast<std::size_t>(n));
        pbump(static_cast<int>(n));
        return n;
    }
    flushNow();
    if (static_cast<std::size_t>(n) >= buffer_.size()) {
        writeAll(s, static_cast<std::size_t>(n));
        return n;
    }
    std::memcpy(pptr(), s, static_cast<std::size_t>(n));
    pbump(static_cast<int>(n));
    return n;
}

int FdStreamBuf::sync()
{
    flushNow();
    return 0;
}

} // namespace ab
