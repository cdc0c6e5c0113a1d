#include "base/StagedFile.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "base/Error.h"

namespace rigmesh {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& target, const std::string& why) {
    throw Error(MessageId::CannotWriteFile, target.string(), why);
}

std::string systemError(int error) {
    return std::error_code(error, std::generic_category()).message();
}

fs::path folderOf(const fs::path& target) {
    return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// A name no other writer (thread or process) uses at the same time.
fs::path temporaryBeside(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    return folderOf(target) / ("." + target.filename().string() + "." + std::to_string(::getpid()) +
                               "-" + std::to_string(counter++) + ".tmp");
}

// Writes every byte, retrying short writes; false (errno set) on failure.
bool writeAll(int descriptor, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t written = ::write(descriptor, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0) {
            if (written == 0)
                errno = ENOSPC;
            return false;
        }
        bytes.remove_prefix(static_cast<std::size_t>(written));
    }
    return true;
}

}  // namespace

void checkReplaceable(const fs::path& target) {
    std::error_code error;
    const fs::path folder = folderOf(target);
    if (!fs::is_directory(folder, error))
        throw Error(MessageId::WriteFolderMissing, target.string(), folder.string());
    const fs::file_status status = fs::status(target, error);
    if (fs::is_directory(status))
        throw Error(MessageId::WriteTargetIsFolder, target.string());
    if (!fs::exists(status))
        return;
    // No write bit at all is read-only even for root, who passes access().
    const fs::perms writable =
        fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    if ((status.permissions() & writable) == fs::perms::none || ::access(target.c_str(), W_OK) != 0)
        throw Error(MessageId::WriteReadOnly, target.string());
}

StagedFile::StagedFile(const fs::path& target, std::string_view bytes)
    : target_(target), temporary_(temporaryBeside(target)) {
    checkReplaceable(target_);
    const int descriptor =
        ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (descriptor < 0) {
        const int error = errno;
        throw Error(MessageId::WriteCannotCreate, target_.string(), folderOf(target_).string(),
                    systemError(error));
    }
    // A constructor that throws runs no destructor: remove the file here.
    const auto failAndRemove = [&](const Error& error) {
        std::error_code ignored;
        fs::remove(temporary_, ignored);
        throw error;
    };
    bool ok = writeAll(descriptor, bytes) && ::fsync(descriptor) == 0;
    int error = ok ? 0 : errno;
    if (::close(descriptor) != 0 && ok) {
        ok = false;
        error = errno;
    }
    if (!ok)
        failAndRemove(Error(MessageId::WriteDiskFull, target_.string(), systemError(error)));
    std::error_code ignored;
    const fs::file_status existing = fs::status(target_, ignored);
    if (fs::exists(existing)) {
        std::error_code permissionError;
        fs::permissions(temporary_, existing.permissions(), permissionError);
        if (permissionError)
            failAndRemove(Error(MessageId::WritePermissionsLost, target_.string(),
                                permissionError.message()));
    }
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : target_(std::move(other.target_)), temporary_(std::move(other.temporary_)) {
    other.temporary_.clear();
}

StagedFile::~StagedFile() {
    if (!temporary_.empty()) {
        std::error_code ignored;
        fs::remove(temporary_, ignored);
    }
}

void StagedFile::commit() {
    std::error_code error;
    fs::rename(temporary_, target_, error);
    if (error)
        fail(target_, error.message());  // the destructor removes the temporary file
    temporary_.clear();
}

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
    StagedFile(path, bytes).commit();
}

}  // namespace rigmesh
