#include "base/large_stack.h"

#include <pthread.h>
#include <unistd.h>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

namespace shaderport {
namespace {

// Set on the threads this file starts: work already on a large stack runs in place.
thread_local bool on_large_stack = false;

void* Trampoline(void* arg) {
  on_large_stack = true;
  (*static_cast<const std::function<void()>*>(arg))();
  return nullptr;
}

// A thread with a large stack that runs one piece of work at a time for its owner.
class LargeStackThread {
 public:
  LargeStackThread() : pid_(getpid()) {
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) != 0) return;
    started_ = pthread_attr_setstacksize(&attr, kLargeStackBytes) == 0 &&
               pthread_create(&thread_, &attr, &Loop, this) == 0;
    pthread_attr_destroy(&attr);
  }

  ~LargeStackThread() {
    if (!started_) return;
    {
      std::lock_guard lock(mutex_);
      quit_ = true;
    }
    wake_.notify_all();
    pthread_join(thread_, nullptr);
  }

  LargeStackThread(const LargeStackThread&) = delete;
  LargeStackThread& operator=(const LargeStackThread&) = delete;

  bool Started() const { return started_; }
  bool OwnedByThisProcess() const { return pid_ == getpid(); }

  void Run(const std::function<void()>& work) {
    std::unique_lock lock(mutex_);
    work_ = &work;
    wake_.notify_all();
    done_.wait(lock, [&] { return work_ == nullptr; });
  }

 private:
  static void* Loop(void* arg) {
    auto* self = static_cast<LargeStackThread*>(arg);
    on_large_stack = true;
    std::unique_lock lock(self->mutex_);
    while (true) {
      self->wake_.wait(lock, [&] { return self->quit_ || self->work_ != nullptr; });
      if (self->work_ == nullptr) return nullptr;  // quit, nothing pending
      const std::function<void()>* work = self->work_;
      lock.unlock();
      (*work)();
      lock.lock();
      self->work_ = nullptr;
      self->done_.notify_all();
    }
  }

  const pid_t pid_;
  pthread_t thread_{};
  bool started_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void()>* work_ = nullptr;
  bool quit_ = false;
};

// Threads inherited through fork() exist only in the parent: their objects are
// kept here, never used or destroyed (their mutex may have been held at the fork).
std::vector<LargeStackThread*>& ForkedAway() {
  static auto* list = new std::vector<LargeStackThread*>;
  return *list;
}

// The calling thread's worker. Joined when the calling thread exits, unless the
// slot was copied into a forked child that exits normally: the thread does not
// exist there, and joining it or destroying its condition variables could hang.
struct WorkerSlot {
  LargeStackThread* worker = nullptr;

  WorkerSlot() = default;
  WorkerSlot(const WorkerSlot&) = delete;
  WorkerSlot& operator=(const WorkerSlot&) = delete;
  ~WorkerSlot() {
    if (worker != nullptr && !worker->OwnedByThisProcess()) {
      ForkedAway().push_back(worker);
      return;
    }
    delete worker;
  }
};

}  // namespace

bool RunOnLargeStack(const std::function<void()>& work, size_t stack_bytes) {
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) return false;
  pthread_t thread;
  bool started =
      pthread_attr_setstacksize(&attr, stack_bytes) == 0 &&
      pthread_create(&thread, &attr, &Trampoline, const_cast<std::function<void()>*>(&work)) == 0;
  pthread_attr_destroy(&attr);
  if (started) pthread_join(thread, nullptr);
  return started;
}

bool RunOnLongLivedLargeStack(const std::function<void()>& work) {
  if (on_large_stack) {
    work();
    return true;
  }
  thread_local WorkerSlot slot;
  if (slot.worker != nullptr && !slot.worker->OwnedByThisProcess()) {
    ForkedAway().push_back(slot.worker);
    slot.worker = nullptr;
  }
  if (slot.worker == nullptr) {
    auto worker = std::make_unique<LargeStackThread>();
    if (!worker->Started()) return RunOnLargeStack(work);
    slot.worker = worker.release();
  }
  slot.worker->Run(work);
  return true;
}

}  // namespace shaderport
