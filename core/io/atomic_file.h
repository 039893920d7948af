// SPDX-License-Identifier: MIT
// The one way both programs write a file (docs/files.md lists what it guarantees):
//
// - a regular file (new or existing) is written whole or not at all: into a temporary
//   file beside it, then renamed over it, so a reader never sees a half-written file; an
//   existing file keeps its mode and, where the process may, its owner and group;
// - a read-only file is refused, also for root; a folder is refused;
// - a symbolic link is followed: the file it names is written (atomically, beside it);
// - a target that is not a regular file (a device such as /dev/null, a FIFO) is written
//   directly, never replaced; a FIFO with no reader is refused instead of waiting;
// - every write, flush, sync and close is checked: a full disk, a quota or a file size
//   limit is an OutputError naming the file and the reason; the old file is kept;
// - the temporary file is removed on every path out: an error, an exception, and (with
//   removeTempFilesOnSignals) SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE; its name is
//   cut to fit the file system's limit whenever the target's own name fits.
#pragma once

#include "../params.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ab {

// Writing failed after it began (disk full, quota, file size limit, I/O error, a closed
// standard output). What was there before is kept. The CLI's exit status for it is 4; the
// window shows it as it shows a bad file name (it is an InputError).
class OutputError : public InputError {
public:
    using InputError::InputError;
};

// An output file being written. The constructor checks the target (InputError for a bad
// one: no folder, a folder, read-only, a FIFO without a reader) and opens the temporary
// file; stream() takes the content (its exceptions() include badbit: a failed write
// throws OutputError at once); commit() makes the file whole in place. Destroyed without
// commit(), the temporary file is removed and the target is untouched.
class OutputFile {
public:
    explicit OutputFile(const std::filesystem::path& path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::ostream& stream();
    void write(std::string_view bytes) { stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size())); }
    // Flushes, syncs and closes (all checked), then renames the temporary file into place.
    void commit();

    // The file that is written: the named path with symbolic links followed.
    const std::filesystem::path& target() const;
    // True when the target is written in place (a device or FIFO).
    bool direct() const;

    struct Impl;

private:
    std::unique_ptr<Impl> d_;
};

// OutputFile in one call: `write` fills the stream, then the file is committed. An
// exception from `write` leaves the target untouched and no temporary file.
void writeFileAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// Checks early (before a long run) that `path` can be written, with the same message
// OutputFile would give; creates nothing.
void checkWritable(const std::filesystem::path& path);

// Installs handlers that remove every temporary file being written, then end the process
// by the same signal, for SIGHUP, SIGQUIT and SIGPIPE and, when `alsoInterrupts`, SIGINT
// and SIGTERM (a program with its own SIGINT handler calls removeTempFilesNow from it).
// A signal the process inherited as ignored stays ignored. SIGXFSZ is ignored, so that a
// file size limit is an OutputError ("File too large") rather than a core dump.
void removeTempFilesOnSignals(bool alsoInterrupts);
// Async-signal-safe: unlinks the temporary files being written now.
void removeTempFilesNow() noexcept;

// The one-line text of a failed write of `name`, for errno `error` ("the disk is full").
std::string writeFailure(const std::string& name, int error);

} // namespace ab
