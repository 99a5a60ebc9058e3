#include "game/files/text_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace game {

LoadError::LoadError(const std::string& f, const std::string& p, const std::string& m)
    : std::runtime_error(printable(f) + ": " + printable(p) + ": " + printable(m)),
      file(printable(f)), path(printable(p)), detail(printable(m)) {}

namespace {

/// Length of the UTF-8 sequence starting at text[i] (1..4), or 0 when the bytes there are
/// not valid UTF-8 (overlong forms, surrogates and code points past U+10FFFF included).
std::size_t utf8Sequence(const std::string& text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned c = byte(i);
    if (c < 0x80) return 1;
    std::size_t n = 0;
    unsigned cp = 0;
    if ((c & 0xe0) == 0xc0)
        n = 2, cp = c & 0x1f;
    else if ((c & 0xf0) == 0xe0)
        n = 3, cp = c & 0x0f;
    else if ((c & 0xf8) == 0xf0)
        n = 4, cp = c & 0x07;
    else
        return 0;
    if (i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xc0) != 0x80) return 0;
        cp = (cp << 6) | (byte(i + k) & 0x3f);
    }
    const unsigned least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < least[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return 0;
    return n;
}

} // namespace

std::string printable(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8Sequence(text, i);
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (n == 0 || (n == 1 && ((c < 0x20 && c != '\t') || c == 0x7f))) {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
            ++i;
        } else {
            out.append(text, i, n);
            i += n;
        }
    }
    return out;
}

std::size_t characterCount(const std::string& text) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < text.size(); ++count)
        i += std::max<std::size_t>(1, utf8Sequence(text, i));
    return count;
}

std::string readFile(const std::string& file) {
    // Opened without blocking (a FIFO with no writer would wait for ever), then judged by
    // what it is before a byte is read: /dev/zero never ends, a directory has no text.
    const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        throw LoadError(file, "$", "cannot open the file (does it exist and is it readable?)");
    struct ::stat st {};
    const bool known = ::fstat(fd, &st) == 0;
    if (!known || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw LoadError(file, "$",
                        std::string("expected a regular file, got ") +
                            (!known                 ? "something that cannot be examined"
                             : S_ISDIR(st.st_mode)  ? "a directory"
                             : S_ISFIFO(st.st_mode) ? "a FIFO (named pipe)"
                             : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)
                                 ? "a device"
                                 : "a socket or other special file"));
    }
    if (static_cast<unsigned long long>(st.st_size) > kMaxFileBytes) {
        ::close(fd);
        throw LoadError(file, "$",
                        "the file is " + std::to_string(st.st_size) + " bytes; files of at most " +
                            std::to_string(kMaxFileBytes) + " bytes (16 MiB) are read");
    }
    std::string text;
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            ::close(fd);
            throw LoadError(file, "$", "reading the file failed");
        }
        if (n == 0) break;
        text.append(buf, static_cast<std::size_t>(n));
        if (text.size() > kMaxFileBytes) { // it grew while being read
            ::close(fd);
            throw LoadError(file, "$",
                            "the file grew past " + std::to_string(kMaxFileBytes) +
                                " bytes while being read");
        }
    }
    ::close(fd);
    return text;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    // Each failure names the file and the system's reason (no space left, a file size
    // limit, permission), and removes the temporary file: the target is untouched.
    auto failed = [&](const std::string& what, int error) {
        ::unlink(tmp.c_str());
        throw std::runtime_error(path + ": " + what + ": " + std::strerror(error));
    };
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) {
        const int error = errno;
        throw std::runtime_error(path + ": cannot create " + tmp + ": " + std::strerror(error));
    }
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;
            ::close(fd);
            failed("writing failed", error);
        }
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) {
        const int error = errno;
        ::close(fd);
        failed("flushing to disk failed", error);
    }
    if (::close(fd) != 0) failed("flushing to disk failed", errno);
    if (std::rename(tmp.c_str(), path.c_str()) != 0) failed("cannot replace the file", errno);
}

std::string contentHash(const std::string& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

} // namespace game
