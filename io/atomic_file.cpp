#include "arealight/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace arealight {

bool write_file_atomic(const std::string& path, const std::string& bytes,
                       const DiagnosticConsumer& diag) {
    auto fail = [&](const std::string& tmp, int err) {
        if (!tmp.empty()) ::unlink(tmp.c_str());
        if (diag) diag({Severity::Error, path, 0, path + ": cannot write: " + std::strerror(err)});
        return false;
    };
    // Same directory as the destination, so rename() cannot cross file systems.
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return fail("", errno);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            return fail(tmp, err);
        }
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) return fail(tmp, errno);
    if (::rename(tmp.c_str(), path.c_str()) != 0) return fail(tmp, errno);
    return true;
}

}  // namespace arealight
