#pragma once
// A robot's single server (SimPy's Resource with capacity 1): the searches and verifications it
// was asked for wait in one first-in-first-out queue and are served one at a time. Serving a
// search takes service.fixed + service.per_comparison x what the search compared, serving a
// verification service.fixed; RobotLoad counts both, the time spent and the longest wait line.
//
// A search's work is the method's (`Job` holds what it needs of one query): it searches when the
// service starts (what is stored then) and delivers its answer when the service time has elapsed.
// A robot that went offline (AgentCore::GoOffline) queues nothing, and the task it was serving
// ends without effect.
#include <algorithm>
#include <cstdint>
#include <utility>

#include "agents/agent_core.h"
#include "agents/reuse_queue.h"

namespace dvpr {

template <class Job>
class TaskServer : public AgentCore {
 protected:
  struct Task {
    enum class Kind { kSearch, kVerify } kind = Kind::kSearch;
    bool store = false;  // kSearch: keep the query after searching
    RobotId querier;
    FrameId frame;
    FrameId match_frame;  // kVerify
    Job job;              // kSearch: the method's (reset to Job{} for each task)
  };

  using AgentCore::AgentCore;

  // Queues a search of `querier`'s frame; fill(job) sets the method's part. Nothing while offline.
  template <class Fill>
  void EnqueueSearch(RobotId querier, FrameId frame, bool store, Fill&& fill) {
    if (!online_) return;
    Task& task = PushTask(Task::Kind::kSearch, querier, frame);
    task.store = store;
    std::forward<Fill>(fill)(task.job);
    Enqueued();
  }
  void EnqueueVerify(RobotId querier, FrameId frame, FrameId match_frame) final {
    if (!online_) return;
    PushTask(Task::Kind::kVerify, querier, frame).match_frame = match_frame;
    Enqueued();
  }
  void DropWaiting() final { queue_.clear(); }

  // The method's search, at the start of the task's service: what it compared (the service
  // time's count); it keeps the answer until Searched.
  virtual std::int64_t Search(Task& task) = 0;
  // The service ended: the method stores and answers.
  virtual void Searched(const Task& task) = 0;

  bool busy_ = false;
  Task in_service_;  // when busy_ (written by PushTask when idle, else swapped with the queue's front slot)
  ReuseQueue<Task> queue_;

 private:
  // The back slot with every field reset (the message its job held, if any, let go); an idle
  // robot's task goes straight into service (its queue is empty: StartNextTask empties it before
  // it idles), not through a queue slot and a swap.
  Task& PushTask(typename Task::Kind kind, RobotId querier, FrameId frame) {
    Task& task = busy_ ? queue_.Push() : in_service_;
    task.kind = kind;
    task.store = false;
    task.querier = querier;
    task.frame = frame;
    task.match_frame = FrameId();
    task.job = Job{};
    return task;
  }

  // After PushTask: serves the task now if the robot was idle.
  void Enqueued() {
    if (busy_) {
      load_.max_queue = std::max<std::int64_t>(load_.max_queue, static_cast<std::int64_t>(queue_.size()));
      return;
    }
    busy_ = true;  // PushTask put the task in service
    Serve();
  }

  void StartNextTask() {
    if (busy_ || queue_.empty() || !online_) return;
    busy_ = true;
    queue_.PopInto(in_service_);
    Serve();
  }

  // The timers hold only the agent, so scheduling them does not allocate.
  void Serve() {
    if (in_service_.kind == Task::Kind::kSearch) {
      const std::int64_t comparisons = Search(in_service_);
      const SimTime duration = params_.service.fixed + params_.service.per_comparison * comparisons;
      ++load_.searches;
      if (in_service_.querier != id_) ++load_.remote_queries;
      load_.comparisons += comparisons;
      load_.busy += duration;
      transport_.ScheduleAfter(duration, [this] { FinishSearch(); });
    } else {
      ++load_.verifications;
      load_.busy += params_.service.fixed;
      transport_.ScheduleAfter(params_.service.fixed, [this] { FinishVerify(); });
    }
  }

  void FinishSearch() {
    if (!online_) return;
    Searched(in_service_);
    EndService();
  }

  void FinishVerify() {
    if (!online_) return;
    FinishVerification(in_service_.querier, in_service_.frame, in_service_.match_frame);
    EndService();
  }

  // The finished task lets go of its job (a decoded message goes back to the pool once the other
  // robots that queued it are done with it too).
  void EndService() {
    in_service_.job = Job{};
    busy_ = false;
    StartNextTask();
  }
};

}  // namespace dvpr
