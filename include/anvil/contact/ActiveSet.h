// The active set of a penalty contact term (docs/design.md §3), one flag per
// constraint, driven by its gap velocity h (mm/s; h > 0 closes the gap).
// For the first Newton iterations it follows the sign of h at the last
// iterate (semi-smooth Newton); then it is frozen so Newton sees a smooth
// problem, and once Newton has converged it is checked: a constraint with
// tensile contact stress (h < 0) is released, a free one that penetrates
// (h > 0) is added, and Newton goes on until the set no longer changes.
// A constraint changes side only beyond a tolerance: at the edge of a contact
// zone the exact solution has h = 0 and σn = 0 together, and a strict test
// would cycle between the two sets. Beyond the tolerance the sets can still
// cycle (a few nodes at the edge tensile with them, penetrating without:
// upsetting_75 at 0.75 mm went 363, 360, 363, ... nodes to the budget of ten
// changes): a set that asks for one Newton has already converged with is a
// cycle, and the union of the two sets is taken and accepted once Newton
// converges with it (no node inside a die; those it adds carry a small
// tension for the increment). A constraint a check releases is watched at
// the next accepted iterate: if it penetrates there, the release is that
// cycle seen one step in, before Newton pays for converging a set that
// would only ask it back, and the constraint is held active for the rest of
// the increment (the connecting rod's corner node against a drafted cavity
// wall, with the set following five iterates: released at h = -1.3e-3
// mm/s, 20 Newton iterations of cut steps to converge without it, then
// h = +0.17 mm/s; held, 15 iterations for the increment instead of 34).
// Newton need not converge a set it is about to leave: near convergence
// (IncrementSolver) the set may move to one it has not had in this increment,
// so a contact zone whose edge recedes node by node does not pay a full
// quadratic tail per node. There a constraint changes side only if it is
// beyond the tolerance by more than the last Newton step moved its h (the
// step bounds the iterate's error once Newton converges superlinearly); a
// set it has had waits for convergence, so these moves cannot cycle, and only
// sets Newton converged with count as a cycle.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace anvil::contact {

class ActiveSet {
public:
  void resize(std::size_t constraints) {
    active_.assign(constraints, 0);
    held_.assign(constraints, 0);
  }
  void set_tolerance(double gap_tolerance) { tolerance_ = gap_tolerance; }

  /// Newton starts: a constraint touching with no relative normal velocity
  /// (h = 0) starts active, so a body resting on another is supported.
  void start(const std::vector<double>& gap) {
    frozen_ = false;
    iterations_ = 0;
    converged_with_.clear();
    left_near_convergence_.clear();
    settled_ = false;
    for (std::size_t i = 0; i < active_.size(); ++i)
      active_[i] = gap[i] >= -tolerance_;
    released_.clear();
    std::fill(held_.begin(), held_.end(), 0);
    gap_last_ = gap;
    gap_before_ = gap;
  }
  /// An accepted Newton iterate: the set follows h until it freezes. Returns the log note.
  std::string accept(const std::vector<double>& gap, const char* what) {
    int activated = 0, released = 0, active = 0;
    gap_before_.swap(gap_last_);
    gap_last_ = gap;
    for (std::size_t i = 0; i < active_.size(); ++i) {
      const char now = frozen_ ? active_[i] : wants(i, gap[i], 0.0);
      activated += now && !active_[i];
      released += !now && active_[i];
      active += now;
      active_[i] = now;
    }
    for (const std::size_t i : released_) // released by the last check, it penetrates: back in, held
      if (gap[i] > tolerance_) {
        held_[i] = 1;
        activated += !active_[i];
        active += !active_[i];
        active_[i] = 1;
      }
    released_.clear();
    frozen_ = ++iterations_ >= kFreezeAfter;
    last_changes_ = activated + released;
    return std::string("  ") + what + " " + std::to_string(active) + " (+" + std::to_string(activated) + " -" +
           std::to_string(released) + ")" + (frozen_ ? " frozen" : "");
  }
  /// Newton converged (`converged`) or is near convergence: true if the set
  /// agrees with h (or the set is a cycle's union, above); otherwise it is
  /// updated. Near convergence `gap` is that of the last accepted iterate,
  /// a constraint changes only beyond its error, and a set already had in
  /// this increment is left for the check at convergence.
  bool consistent(const std::vector<double>& gap, bool converged) {
    if (settled_) return true;
    std::vector<char> now(active_.size());
    for (std::size_t i = 0; i < active_.size(); ++i)
      now[i] = wants(i, gap[i], converged ? 0.0 : std::abs(gap[i] - gap_before_[i]));
    if (now == active_) return true;
    if (!converged) {
      if (had(left_near_convergence_, now) || had(converged_with_, now)) return true;
      left_near_convergence_.push_back(active_);
      take(now);
      return false;
    }
    converged_with_.push_back(active_);
    if (had(converged_with_, now)) {
      for (std::size_t i = 0; i < active_.size(); ++i)
        now[i] = now[i] || active_[i];
      settled_ = true;
      if (now == active_) return true;
    }
    take(now);
    return false;
  }

  /// Constraints the last accept() activated or released.
  int last_changes() const { return last_changes_; }
  /// True while accept() still moves the set with the iterates (not yet frozen).
  bool following() const { return !frozen_; }
  bool operator[](std::size_t i) const { return active_[i] != 0; }
  std::size_t size() const { return active_.size(); }
  int count() const {
    int n = 0;
    for (char a : active_)
      n += a;
    return n;
  }

private:
  /// The side constraint i wants with gap velocity h known to within `error`.
  bool wants(std::size_t i, double h, double error) const {
    return active_[i] ? held_[i] || h + error > -tolerance_ : h - error > tolerance_;
  }
  /// A check's new set; the constraints it releases are watched at the next accepted iterate.
  void take(std::vector<char>& set) {
    released_.clear();
    for (std::size_t i = 0; i < active_.size(); ++i)
      if (active_[i] && !set[i]) released_.push_back(i);
    active_.swap(set);
  }
  static bool had(const std::vector<std::vector<char>>& sets, const std::vector<char>& set) {
    return std::find(sets.begin(), sets.end(), set) != sets.end();
  }

  std::vector<char> active_;
  std::vector<std::vector<char>> converged_with_;        ///< the sets Newton converged with in this increment
  std::vector<std::vector<char>> left_near_convergence_; ///< the sets left before Newton converged with them
  std::vector<std::size_t> released_; ///< released by the last check: held if the next iterate has it penetrate
  std::vector<char> held_;            ///< released by a check, then penetrating: active for the rest of the increment
  std::vector<double> gap_last_, gap_before_; ///< h at the last two accepted iterates
  bool settled_ = false;                      ///< a cycle's union taken: accepted at the next convergence
  double tolerance_ = 0.0;                    ///< mm/s
  bool frozen_ = false;
  int iterations_ = 0;
  int last_changes_ = 0;
  static constexpr int kFreezeAfter = 3;
};

} // namespace anvil::contact
