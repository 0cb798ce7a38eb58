#pragma once
// All the files one command writes, committed together (issue 17): each
// output is written to a temporary created exclusively (O_CREAT|O_EXCL|
// O_NOFOLLOW) beside its target, and only commit() renames them into place.
// Destruction without commit, SIGINT and SIGTERM remove the temporaries, so a
// failed or interrupted command leaves no output at all.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace vri {

class OutputTransaction {
 public:
  // Becomes the active transaction: write_file_atomically() stages into it.
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // Writes `bytes` to a fresh temporary beside `target`; throws vri::Error.
  void stage(const std::filesystem::path& target, std::span<const std::byte> bytes);
  // The same for a file made of `parts`, one after another (a header and an
  // image's pixels, without a copy of them side by side).
  void stage(const std::filesystem::path& target, std::span<const std::span<const std::byte>> parts);
  // Renames every staged temporary onto its target; throws vri::Error (and
  // removes the temporaries not yet renamed) if one cannot be.
  void commit();
  // Creates the folder `dir` (and its missing parents) for outputs staged in
  // it; without a commit they are removed again, once empty (a turntable
  // that failed left an empty frames folder, issue 47).
  void create_directories(const std::filesystem::path& dir);

  // The active transaction of this process, or nullptr.
  static OutputTransaction* active();

 private:
  struct Staged {
    std::filesystem::path temp, target;
  };
  std::vector<Staged> staged_;
  std::vector<std::filesystem::path> created_;  // folders made here, deepest first
  OutputTransaction* previous_;
  void discard() noexcept;
};

// Installs SIGINT/SIGTERM handlers that unlink every temporary still staged,
// then re-raise the signal with its default action; ignores SIGXFSZ, so a
// write past the file-size limit fails (EFBIG) and the transaction cleans up
// instead of the process dying with its temporaries left.
void remove_temporaries_on_signal();

}  // namespace vri
