#pragma once
// Progress of many parallel jobs of one kind, reported at every tenth done
// ("NAME: WHAT: k/N solved"), so that a run of thousands of jobs says ten
// lines, not thousands. Safe to call from any thread; silent without a
// progress callback or with no jobs.
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>

namespace sg {

class TenthsProgress {
 public:
  TenthsProgress(const std::function<void(const std::string&)>& progress, std::string label, std::size_t total)
      : progress_(progress), label_(std::move(label)), total_(total) {}
  // One job finished.
  void done() {
    if (!progress_ || total_ == 0) return;
    std::lock_guard lock(mutex_);
    ++done_;
    if (done_ * 10 / total_ != (done_ - 1) * 10 / total_)
      progress_(label_ + ": " + std::to_string(done_) + "/" + std::to_string(total_) + " solved");
  }

 private:
  const std::function<void(const std::string&)>& progress_;
  std::string label_;
  std::size_t total_ = 0, done_ = 0;
  std::mutex mutex_;
};

}  // namespace sg
