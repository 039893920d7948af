// SPDX-License-Identifier: MIT
// An output stream over a file descriptor whose every write is checked: a failed write
// throws OutputError with the reason (the stream's exceptions() include badbit, so the
// exception reaches the caller). A write cut short by a signal is retried unless an
// interrupt was requested (then Interrupted is thrown). Used for output files and for
// the command line's standard output.
#pragma once

#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace ab {

class FdStreamBuf : public std::streambuf {
public:
    // `name` is how messages name the destination ("out.csv", "standard output"); `suffix`
    // ends them ("; the old file is kept").
    FdStreamBuf(int fd, std::string name, std::string suffix = {});
    // Writes what is buffered; throws OutputError when it cannot.
    void flushNow();
    // Drops what is buffered (after a failure, so that nothing is retried on destruction).
    void discard() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
    int fd() const { return fd_; }

protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    int sync() override;

private:
    void writeAll(const char* data, std::size_t size);

    int fd_;
    std::string name_, suffix_;
    std::vector<char> buffer_;
};

class FdOStream : public std::ostream {
public:
    FdOStream(int fd, std::string name, std::string suffix = {})
        : std::ostream(nullptr), buf_(fd, std::move(name), std::move(suffix))
    {
        rdbuf(&buf_);
        exceptions(std::ios::badbit);
    }
    FdStreamBuf& buf() { return buf_; }

private:
    FdStreamBuf buf_;
};

} // namespace ab
