#include "core/io/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <streambuf>

#include "core/scene/file_names.hpp"

namespace pbr {

namespace fs = std::filesystem;

namespace {

// The temporaries being written, for the signal handler to remove: fixed storage, so that the handler reads no
// memory that may be freed under it. A slot is claimed before its path is copied in and marked live after.
constexpr size_t kTemporarySlots = 64;
constexpr size_t kTemporaryPathBytes = 4096;
std::array<std::array<char, kTemporaryPathBytes>, kTemporarySlots> gTemporaryPaths{};
std::array<std::atomic<int>, kTemporarySlots> gTemporaryState{};  // 0 free, 1 being written, 2 live

// The slot holding `path`, or -1 when every slot is taken or the path is too long (the temporary is then not
// removed on a signal: only on the normal paths).
int registerTemporary(const std::string& path) {
  if (path.size() >= kTemporaryPathBytes) return -1;
  for (size_t i = 0; i < kTemporarySlots; ++i) {
    int expected = 0;
    if (!gTemporaryState[i].compare_exchange_strong(expected, 1)) continue;
    std::memcpy(gTemporaryPaths[i].data(), path.c_str(), path.size() + 1);
    gTemporaryState[i].store(2);
    return int(i);
  }
  return -1;
}

void releaseTemporary(int slot) {
  if (slot >= 0) gTemporaryState[size_t(slot)].store(0);
}

extern "C" void removeTemporariesAndStop(int signal) {
  for (size_t i = 0; i < kTemporarySlots; ++i) {
    if (gTemporaryState[i].load() == 2) ::unlink(gTemporaryPaths[i].data());
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void removeTemporariesOnSignals() {
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) std::signal(s, removeTemporariesAndStop);
  // Past a file-size limit, write(2) then fails with EFBIG, which the writer reports naming the file.
  std::signal(SIGXFSZ, SIG_IGN);
}

std::string followLinks(const std::string& path) {
  fs::path p(path);
  std::error_code ec;
  // As the kernel does, at most 40 links in a chain.
  for (int i = 0; i < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++i) {
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) break;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  const fs::path resolved = fs::weakly_canonical(p, ec);
  return ec ? p.lexically_normal().string() : resolved.string();
}

// A stream buffer writing straight to a file descriptor, so that the errno of the first failed write(2) or
// close(2) is kept for the message instead of a stream's bare failbit.
class OutputFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd) { setp(data_, data_ + sizeof data_); }
  ~Buffer() override {
    if (fd_ >= 0) ::close(fd_);
  }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // Writes what is buffered and closes: 0, or the errno of the first failure.
  int close() {
    drain();
    if (::close(fd_) != 0 && error_ == 0) error_ = errno;
    fd_ = -1;
    return error_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    for (const char* p = pbase(); p < pptr() && error_ == 0;) {
      const ssize_t n = ::write(fd_, p, static_cast<size_t>(pptr() - p));
      if (n > 0) p += n;
      else if (n == 0) error_ = EIO;  // no progress on a non-empty write: never wait on it
      else if (errno != EINTR) error_ = errno;
    }
    setp(data_, data_ + sizeof data_);
    return error_ == 0;
  }

  int fd_;
  int error_ = 0;
  char data_[1 << 16];
};

OutputFile::OutputFile(std::string path) : path_(std::move(path)), target_(path_) {
  if (path_.empty()) throw std::runtime_error("(empty path): cannot write: no file named");
  std::error_code ec;
  // A symbolic link keeps pointing where it did: the temporary goes beside the file it names, which is made where
  // it does not exist yet.
  if (fs::is_symlink(fs::symlink_status(target_, ec))) target_ = followLinks(target_);
  int fd = -1;
  struct stat st {};
  if (::stat(target_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) fail("a directory");
    // A device or FIFO cannot be replaced by a rename and holds no partial file: written in place, checked.
    fd = ::open(target_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) fail(std::strerror(errno));
  } else {
    const fs::path target(target_);
    if (!target.has_filename()) fail("names a folder, not a file");
    const fs::path folder = target.parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec)) {
      fs::create_directories(folder, ec);
      if (ec) fail("cannot make the folder " + folder.string() + ": " + ec.message());
    }
    static std::atomic<unsigned> counter{0};
    do {
      temporary_ = (folder / ("." + target.filename().string() + "." + std::to_string(::getpid()) + "." +
                              std::to_string(counter++) + ".tmp"))
                       .string();
      fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    } while (fd < 0 && errno == EEXIST);
    if (fd < 0) {
      const int error = errno;
      temporary_.clear();  // never created: nothing to remove
      fail(std::strerror(error));
    }
    signalSlot_ = registerTemporary(temporary_);
  }
  buffer_ = std::make_unique<Buffer>(fd);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() {
  stream_.reset();
  buffer_.reset();
  if (!committed_ && !temporary_.empty()) ::unlink(temporary_.c_str());
  releaseTemporary(signalSlot_);
}

std::ostream& OutputFile::stream() { return *stream_; }

void OutputFile::commit() {
  stream_->flush();
  if (const int error = buffer_->close()) fail(std::strerror(error));
  if (!*stream_) fail("the data could not be formatted");
  if (!temporary_.empty() && ::rename(temporary_.c_str(), target_.c_str()) != 0) fail(std::strerror(errno));
  committed_ = true;
  releaseTemporary(signalSlot_);
  signalSlot_ = -1;
}

void OutputFile::fail(const std::string& reason) {
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
  releaseTemporary(signalSlot_);
  signalSlot_ = -1;
  throw std::runtime_error(path_ + ": cannot write: " + reason);
}

void OutputFile::write(const std::function<void(std::ostream&)>& body) {
  try {
    body(stream());
  } catch (const std::runtime_error& e) {
    fail(e.what());
  }
  commit();
}

bool isStreamTarget(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode));
}

void makeOutputFolder(const std::string& option, const std::string& dir) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw std::runtime_error(option + " " + dir + ": cannot make the folder: " +
                             (ec ? ec.message() : std::string("a file is in the way")));
  }
}

void writeOutputFile(const std::string& path, const std::function<void(std::ostream&)>& body) {
  OutputFile(path).write(body);
}

void requireExtension(const std::string& path, const std::string& extension) {
  if (lowerExtension(path) != extension && !isStreamTarget(path)) {
    throw std::invalid_argument(path + ": expected a " + extension + " file");
  }
}

}  // namespace pbr
