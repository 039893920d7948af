// SPDX-License-Identifier: MIT
#include "atomic_file.h"

#include "fd_stream.h"
#include "temp_registry.h"

#include "../params.h"

#include <cerrno>
#include <climits>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

namespace ab {

namespace {

namespace fs = std::filesystem;

std::string shown(const fs::path& path)
{
    return printableInput(path.string());
}

fs::path folderOf(const fs::path& path)
{
    const fs::path parent = path.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

// What is at the end of `path`'s symbolic links (at most 40, as the kernel allows).
fs::path followLinks(const fs::path& path)
{
    fs::path at = path;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat st {};
        if (::lstat(at.c_str(), &st) != 0 || !S_ISLNK(st.st_mode))
            return at;
        std::error_code ec;
        const fs::path link = fs::read_symlink(at, ec);
        if (ec)
            throw InputError(shown(path) + ": cannot read the symbolic link (" + ec.message() + ")");
        at = link.is_absolute() ? link : folderOf(at) / link;
    }
    throw InputError(shown(path) + ": too many levels of symbolic links");
}

// The target, checked: where it is, what it is, and what an existing file keeps.
struct Target {
    fs::path path;                       // links followed
    std::optional<struct stat> existing; // a regular file already there
    bool direct = false;                 // a device, FIFO or socket: written in place
};

Target examine(const fs::path& named)
{
    if (named.empty())
        throw InputError("output file: the name is empty");
    Target t{followLinks(named), std::nullopt, false};
    const std::string name = shown(named);
    struct stat st {};
    if (::stat(t.path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode))
            throw InputError(name + ": is a folder, not a file");
        if (!S_ISREG(st.st_mode)) {
            t.direct = true; // never replaced by a regular file
            return t;
        }
        // Root may write any file; a file nobody may write is still refused, as a
        // careful tool does (a read-only file is meant to stay as it is).
        const bool readOnly = ::geteuid() == 0 ? (st.st_mode & 0222) == 0 : ::access(t.path.c_str(), W_OK) != 0;
        if (readOnly)
            throw InputError(name + ": the file is read-only; not replaced");
        t.existing = st;
    } else if (errno != ENOENT) {
        throw InputError(name + ": " + std::strerror(errno));
    }
    const fs::path folder = folderOf(t.path);
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw InputError(name + ": folder " + shown(folder) + " does not exist");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError(name + ": folder " + shown(folder) + " is not writable");
    return t;
}

// ".NAME.tmpXXXXXX" beside the target, NAME cut (at a character) so that the whole fits
// the folder's limit for a name.
fs::path tempName(const fs::path& target, std::mt19937_64& random)
{
    const fs::path folder = folderOf(target);
    const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    const std::size_t nameMax = limit > 0 ? static_cast<std::size_t>(limit) : 255;
    static const char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    std::string suffix = ".tmp";
    for (int i = 0; i < 6; ++i)
        suffix += letters[random() % (sizeof letters - 1)];
    std::string base = target.filename().string();
    const std::size_t room = nameMax > suffix.size() + 1 ? nameMax - suffix.size() - 1 : 0;
    if (base.size() > room) {
        std::size_t cut = room;
        while (cut > 0 && (static_cast<unsigned char>(base[cut]) & 0xC0) == 0x80)
            --cut;
        base.resize(cut);
    }
    return folder / ("." + base + suffix);
}

} // namespace

std::string writeFailure(const std::string& name, int error)
{
    std::string why;
    switch (error) {
    case ENOSPC:
        why = "the disk is full";
        break;
    case EDQUOT:
        why = "the disk quota is used up";
        break;
    case EFBIG:
        why = "the file is larger than this process may write";
        break;
    case EPIPE:
        why = "the reader has gone";
        break;
    case EBADF:
        why = "it is closed";
        break;
    default: // the system's words alone, not twice ("Bad file descriptor (Bad file descriptor)")
        return name + ": not written: " + std::strerror(error);
    }
    return name + ": not written: " + why + " (" + std::strerror(error) + ")";
}

struct OutputFile::Impl {
    Target target;
    std::string name; // for messages: the path as the user gave it
    fs::path temp;    // empty when direct
    int fd = -1;
    int slot = -1;
    std::optional<FdOStream> stream;
    bool committed = false;

    void fail(int error)
    {
        throw OutputError(writeFailure(name, error) +
                          (target.direct || !target.existing ? "" : "; the old file is kept"));
    }
};

OutputFile::OutputFile(const fs::path& path) : d_(std::make_unique<Impl>())
{
    d_->target = examine(path);
    d_->name = shown(path);
    const fs::path& target = d_->target.path;
    if (d_->target.direct) {
        // O_NONBLOCK: a FIFO with no reader fails (ENXIO) instead of waiting for one.
        d_->fd = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (d_->fd < 0) {
            const int error = errno;
            if (error == ENXIO)
                throw InputError(d_->name + ": is a FIFO or socket with no reader; nothing written");
            throw InputError(d_->name + ": cannot write there (" + std::strerror(error) + ")");
        }
        ::fcntl(d_->fd, F_SETFL, ::fcntl(d_->fd, F_GETFL) & ~O_NONBLOCK);
    } else {
        std::mt19937_64 random(std::random_device{}());
        for (int attempt = 0; d_->fd < 0; ++attempt) {
            d_->temp = tempName(target, random);
            d_->slot = tempfiles::add(d_->temp.c_str()); // before it exists: a signal then finds it
            // An existing file's mode is set below, once the owner is; until then only we may read.
            d_->fd = ::open(d_->temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY,
                            d_->target.existing ? 0600 : 0666);
            if (d_->fd >= 0)
                break;
            const int error = errno;
            tempfiles::remove(d_->slot);
            d_->slot = -1;
            if (error != EEXIST || attempt > 100)
                throw InputError(d_->name + ": cannot create a file in its folder (" + std::strerror(error) + ")");
        }
        if (const auto& st = d_->target.existing) {
            // Owner first: a change of owner clears the set-id bits that fchmod then restores.
            if (::fchown(d_->fd, st->st_uid, st->st_gid) != 0 && ::fchown(d_->fd, static_cast<uid_t>(-1), st->st_gid))
                errno = 0; // not ours to give away: the new file is the writer's
            ::fchmod(d_->fd, st->st_mode & 07777);
        }
    }
    d_->stream.emplace(d_->fd, d_->name, d_->target.existing ? "; the old file is kept" : "");
}

OutputFile::~OutputFile()
{
    if (d_->committed)
        return;
    if (d_->stream)
        d_->stream->buf().discard();
    if (d_->fd >= 0)
        ::close(d_->fd);
    if (!d_->temp.empty())
        ::unlink(d_->temp.c_str());
    tempfiles::remove(d_->slot);
}

std::ostream& OutputFile::stream()
{
    return *d_->stream;
}

const fs::path& OutputFile::target() const
{
    return d_->target.path;
}

bool OutputFile::direct() const
{
    return d_->target.direct;
}

void OutputFile::commit()
{
    Impl& d = *d_;
    d.stream->buf().flushNow();
    if (!d.target.direct && ::fsync(d.fd) != 0 && errno != EINVAL && errno != EROFS)
        d.fail(errno);
    const int fd = d.fd;
    d.fd = -1;
    if (::close(fd) != 0 && errno != EINTR)
        d.fail(errno);
    if (!d.target.direct) {
        if (::rename(d.temp.c_str(), d.target.path.c_str()) != 0)
            d.fail(errno);
        d.temp.clear();
        tempfiles::remove(d.slot);
        d.slot = -1;
    }
    d.committed = true;
}

void writeFileAtomically(const fs::path& path, const std::function<void(std::ostream&)>& write)
{
    OutputFile file(path);
    write(file.stream());
    file.commit();
}

void writeFileAtomically(const fs::path& path, std::string_view bytes)
{
    OutputFile file(path);
    file.write(bytes);
    file.commit();
}

void checkWritable(const fs::path& path)
{
    const Target t = examine(path);
    if (t.direct) {
        // Opening a FIFO with a reader would hand it an end of file; a FIFO is checked
        // when it is written.
        struct stat st {};
        if (::stat(t.path.c_str(), &st) == 0 && !S_ISFIFO(st.st_mode) && ::access(t.path.c_str(), W_OK) != 0)
            throw InputError(shown(path) + ": cannot write there (" + std::strerror(errno) + ")");
    }
}

} // namespace ab
