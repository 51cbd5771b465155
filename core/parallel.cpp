#include "core/parallel.h"

#include <pthread.h>

#include <algorithm>
#include <exception>

namespace uvtk::detail {
namespace {

// The pool: threads that wait for posted jobs and take the next slot of the first listed one. A
// job stays listed until its last slot is taken or its poster withdraws it; the poster then waits
// for the threads that took slots. Jobs are linked in place, so posting allocates nothing.
class Pool {
 public:
  void post(PostedJob& p) {
    const std::lock_guard<std::mutex> lock(mutex_);
    (last_ ? last_->next : first_) = &p;
    last_ = &p;
    p.listed = true;
    // For a loop no more threads than the cores (or than its own workers, when it asks for more): a
    // loop's worker that waits for a core holds back the caller, which waits for every worker. Work
    // aside gets a thread of its own, as std::async gave it: its poster does not wait for it until
    // it asks (a batch's meshes, each writing its file beside its judgement, fill the cores that way).
    const int limit = p.aside ? kMaxThreads : std::min(kMaxThreads, std::max(threadCount(0), p.job.workers - 1));
    for (int missing = p.job.workers - p.taken - idle_; missing > 0 && threads_ < limit; --missing) {
      try {
        std::thread(&Pool::serve, this).detach();
        ++threads_;
      } catch (const std::exception&) {
        break;  // no thread to give (std::system_error, or no memory for its state): the poster's slot does the work
      }
    }
    wake_.notify_all();
  }

  int withdraw(PostedJob& p) {
    std::unique_lock<std::mutex> lock(mutex_);
    unlist(p);
    p.finished.wait(lock, [&] { return p.running == 0; });
    return p.taken;
  }

 private:
  static constexpr int kMaxThreads = 1024;

  void unlist(PostedJob& p) {
    if (!p.listed) return;
    PostedJob* before = nullptr;
    for (PostedJob* q = first_; q != &p; q = q->next) before = q;
    (before ? before->next : first_) = p.next;
    if (last_ == &p) last_ = before;
    p.next = nullptr;
    p.listed = false;
  }

  void serve() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      ++idle_;
      wake_.wait(lock, [&] { return first_ != nullptr; });
      --idle_;
      PostedJob& p = *first_;
      const int worker = p.taken++;
      if (p.taken == p.job.workers) unlist(p);
      ++p.running;
      lock.unlock();
      p.job.run(p.job.context, worker);
      lock.lock();
      if (--p.running == 0) p.finished.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  PostedJob *first_ = nullptr, *last_ = nullptr;
  int idle_ = 0, threads_ = 0;
};

// Never destroyed: its threads wait to the end of the process. A child of fork() has none of them,
// and the lock may have been held when it was made: the child gets a pool of its own.
std::atomic<Pool*> gPool{nullptr};

Pool& pool() {
  static const bool atFork = [] {
    ::pthread_atfork(nullptr, nullptr, [] { gPool.store(new Pool); });
    return true;
  }();
  (void)atFork;
  Pool* p = gPool.load();
  if (!p) {
    Pool* fresh = new Pool;
    if (gPool.compare_exchange_strong(p, fresh)) return *fresh;
    delete fresh;  // another thread made it first: p holds it
  }
  return *p;
}

}  // namespace

void post(PostedJob& posted) { pool().post(posted); }

int withdraw(PostedJob& posted) { return pool().withdraw(posted); }

void runOnPool(const PoolJob& job) {
  PostedJob posted;
  posted.job = job;
  pool().post(posted);
  job.run(job.context, 0);
  pool().withdraw(posted);
}

}  // namespace uvtk::detail
