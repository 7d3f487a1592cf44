#include <luxplan/core/atomic_file.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include <luxplan/core/error.h>

namespace luxplan {

void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes) {
    const std::filesystem::path temp = file.string() + ".part-" + std::to_string(::getpid());
    auto fail = [&](const char* what, int error) {
        ::unlink(temp.c_str());
        throw IoError(file.string() + ": cannot write (" + what + ": " + std::strerror(error) + ")");
    };
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw IoError(file.string() + ": cannot write (" + std::strerror(errno) + ")");
    for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : EIO;
            ::close(fd);
            fail("write", error);
        }
        done += size_t(n);
    }
    // A full disk may only show when the data reach it.
    if (::fsync(fd) != 0) {
        const int error = errno;
        ::close(fd);
        fail("fsync", error);
    }
    if (::close(fd) != 0) fail("close", errno);
    if (::rename(temp.c_str(), file.c_str()) != 0) fail("rename", errno);
}

}  // namespace luxplan
