// Stopping a stability analysis that is no longer wanted (the app's scene changed, or the app is
// closing): the analysis's long loops (relaxation, Newton, Lanczos, the traced range) call
// check_cancel(), which throws Cancelled once the flag the analysis was given is set; the
// analysis catches it and ends, marked cancelled. The flag is per thread: the analysis sets it on
// its own thread and on each worker it hands a search to (stability.cpp, each_task).
#pragma once

#include <atomic>

namespace springlab {

struct Cancelled {};

namespace cancel_detail {
inline thread_local const std::atomic<bool>* g_flag = nullptr;
}

// Sets the calling thread's flag for the scope of an analysis.
class CancelScope {
 public:
  explicit CancelScope(const std::atomic<bool>* flag) : saved_(cancel_detail::g_flag) {
    cancel_detail::g_flag = flag;
  }
  ~CancelScope() { cancel_detail::g_flag = saved_; }
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  const std::atomic<bool>* saved_;
};

inline void check_cancel() {
  if (cancel_detail::g_flag && cancel_detail::g_flag->load(std::memory_order_relaxed))
    throw Cancelled{};
}

}  // namespace springlab
