#pragma once
// When a periodic action (field snapshot, checkpoint) is due: every `every` steps and/or every
// `period` of simulated time (0: not by that measure).
namespace vp {

class Schedule {
public:
  Schedule(int every, double period, double firstTime) : every_(every), period_(period), next_(firstTime) {}

  bool on() const { return every_ > 0 || period_ > 0; }
  bool due(int step, double time) const
  {
    return (every_ > 0 && step % every_ == 0) || (period_ > 0 && time >= next_ * (1 - 1e-12));
  }
  // The action was taken at (step, time): the next time is the first period end after it.
  void done(int step, double time)
  {
    last_ = step;
    if (period_ > 0)
      while (next_ <= time * (1 + 1e-12)) next_ += period_;
  }
  // A restart: the last step taken and the next time due.
  void resume(int lastStep, double nextTime)
  {
    last_ = lastStep;
    next_ = nextTime;
  }
  int lastStep() const { return last_; }
  double nextTime() const { return next_; }

private:
  int every_;
  double period_, next_;
  int last_ = -1;
};

} // namespace vp
