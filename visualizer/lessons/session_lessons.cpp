// The Session's lessons of the manifest (lessons/manifest.txt): the first, the next and the
// previous one, and their titles for the Lesson menu.
#include "lessons/session.hpp"

namespace sw::vis {

bool Session::open_first_lesson() {
  if (lessons_.empty()) {
    error_ = lessons_error_.empty() ? "no lessons in " + lessons_dir_.string() : lessons_error_;
    return false;
  }
  return open_lesson(lessons_.front());
}

const std::vector<std::string>& Session::lesson_titles() {
  if (lesson_titles_.size() == lessons_.size()) return lesson_titles_;
  lesson_titles_.clear();
  for (const auto& path : lessons_) {
    try {
      lesson_titles_.push_back(load_lesson(path).title);
    } catch (const InputError& e) {  // still listed, so that choosing it shows the error
      lesson_titles_.push_back(path.filename().string() + " (" + e.what() + ")");
    }
  }
  return lesson_titles_;
}

std::optional<std::size_t> Session::lesson_index() const {
  for (std::size_t k = 0; lesson_ && k < lessons_.size(); ++k)
    if (lessons_[k] == lesson_->path) return k;
  return std::nullopt;
}

bool Session::open_adjacent_lesson(int delta) {
  if (lessons_.empty()) return false;
  // Where we are: the lesson open, else the one last tried (it may have failed to load).
  std::optional<std::size_t> at = lesson_index();
  if (!at) at = lesson_pos_;
  const long next = at ? long(*at) + delta : delta > 0 ? 0 : -1;
  if (next < 0 || next >= long(lessons_.size())) return false;
  return open_manifest_lesson(std::size_t(next));
}

bool Session::open_manifest_lesson(std::size_t k) {
  if (k >= lessons_.size()) return false;
  lesson_pos_ = k;
  return open_lesson(lessons_[k]);
}

}  // namespace sw::vis
