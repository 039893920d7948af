// SPDX-License-Identifier: MIT
// The one way both programs open a file to read (docs/files.md): only a regular file is
// read; a FIFO, device, socket or folder is refused with its kind named, without
// blocking (the open is non-blocking and the kind is checked on the open file); the size
// limit is applied before anything is read.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace ab {

// An open regular file, closed on destruction.
class InputFile {
public:
    // `what` opens every message ("--init", "preset 'a.json'"). InputError when the name
    // is empty, the file is missing or unreadable, not a regular file, or larger than
    // `maxBytes`.
    InputFile(const std::filesystem::path& path, const std::string& what, std::size_t maxBytes);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    // Up to `size` bytes; 0 at the end. InputError on a read error.
    std::size_t read(char* into, std::size_t size);
    std::size_t size() const { return size_; }

private:
    int fd_ = -1;
    std::size_t size_ = 0;
    std::string what_;
};

// The whole file (at most `maxBytes`), as above.
std::string readInputFile(const std::filesystem::path& path, const std::string& what, std::size_t maxBytes);

// "a FIFO (named pipe)", "a folder", ... for st_mode's file type.
std::string fileKindName(unsigned mode);

} // namespace ab
