#pragma once
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace pbr {

// Every output file the renderer writes (PNG, EXR, PFM, CSV, JSON, traces) comes through here, so that a failed
// write is always detected and never leaves a partial file behind: the bytes go to a temporary file in the target's
// folder (".NAME.PID.N.tmp"), every write and the close are checked, and only then is the temporary renamed over
// the target. A target that exists and is not a regular file (/dev/stdout, /dev/null, a FIFO) is written directly,
// still checked. Missing folders on the way to the target are made. Failures throw std::runtime_error
// "PATH: cannot write: REASON" and remove the temporary.
class OutputFile {
 public:
  explicit OutputFile(std::string path);  // opens the temporary: an unwritable folder fails here
  ~OutputFile();                           // removes the temporary unless commit() succeeded
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  const std::string& path() const { return path_; }
  std::ostream& stream();
  // Flushes, closes and renames into place; throws on any failure seen since the file was opened.
  void commit();
  // Runs `body` on the stream, then commits; an exception of the body (an encoder's) is rethrown naming the file.
  void write(const std::function<void(std::ostream&)>& body);

 private:
  class Buffer;
  [[noreturn]] void fail(const std::string& reason);

  std::string path_;       // as the user named it, for messages
  std::string target_;     // where the bytes end up (symbolic links resolved)
  std::string temporary_;  // empty when writing the target directly
  int signalSlot_ = -1;    // where removeTemporariesOnSignals finds the temporary, -1 for none
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
  bool committed_ = false;
};

// Installs the handlers that remove every temporary being written when SIGINT, SIGTERM or SIGHUP ends the process
// (then ended by the signal as before), and ignores SIGXFSZ so that a write past a file-size limit fails with
// EFBIG, reported naming the file, instead of killing the process without a word.
void removeTemporariesOnSignals();

// Where `path`'s bytes go once every symbolic link on it is followed, a dangling one included (to the file it
// would name), made absolute and normal.
std::string followLinks(const std::string& path);

// True for an existing device, FIFO or socket: written in place, its name says nothing of the format wanted.
bool isStreamTarget(const std::string& path);

// Refuses (std::invalid_argument naming the file) an output whose name has another extension than the format it
// will hold, e.g. ".json"; a stream target is taken as it is.
void requireExtension(const std::string& path, const std::string& extension);

// Makes the folder an option names for a command's outputs (and its parents), before the work: throws
// std::runtime_error "OPTION DIR: cannot make the folder: REASON" (a file in the way, no permission).
void makeOutputFolder(const std::string& option, const std::string& dir);

// Opens, writes through `body` and commits in one go.
void writeOutputFile(const std::string& path, const std::function<void(std::ostream&)>& body);

}  // namespace pbr
