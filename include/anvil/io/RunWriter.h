// What a run writes to its output folder (docs/design.md §7): the VTK series
// (anvil.pvd), loads.csv (appended each increment), interface.csv (body
// pairs), checkpoint.h5 and summary.json. With several processes rank 0
// alone writes; the others take its answers and its errors.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/io/VtkSeries.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <string>

namespace anvil::io {

class RunWriter {
public:
  /// Writes into `directory` (created beforehand). A resumed run continues
  /// the VTK series of `state` and rewrites loads.csv from its records, which
  /// drops those written after the checkpoint.
  RunWriter(std::string directory, const scene::RunState& state, bool resume);

  /// Writes what is due after increment state.increment (everything when
  /// `force`): loads.csv, the VTK series every case.vtk_every increments,
  /// interface.csv with it, the checkpoint every case.checkpoint_every.
  /// Returns whether a checkpoint was written. Throws RunError.
  bool write(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state, bool force,
             Timers& timers);

  /// The frame part of write (loads.csv, the VTK series, interface.csv) on
  /// its own, for the loop to call before a remesh: the contact fields are
  /// the increment's, on its mesh (a remesh renumbers the nodes its contact
  /// candidates name), and the stresses those of its own solution, not of
  /// velocities transferred onto a new mesh. write then finds the frame
  /// written and adds the checkpoint, of the state after the remesh.
  void write_frame(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state,
                   Timers& timers);

  /// summary.json: the run's figures (`last` is the Newton report of the
  /// last increment, `total` the wall time in s).
  void write_summary(const scene::Scene& scene, const scene::Discretisation& disc, const scene::RunState& state,
                     const solver::NewtonReport& last, const Timers& timers, double total) const;

  /// No checkpoint from here on: the state is not one to resume from (an
  /// increment whose flow was taken but whose heat step failed), so the last
  /// checkpoint written stays the one --resume continues from.
  void stop_checkpoints() { checkpoints_stopped_ = true; }

  const std::string& directory() const { return directory_; }

private:
  bool write_due(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state, bool force,
                 Timers& timers);
  void write_frame_due(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state, bool force,
                       Timers& timers);
  void write_loads(const scene::Scene& scene, const scene::RunState& state);
  void write_vtk(const scene::Scene& scene, const scene::Discretisation& disc, const scene::RunState& state);
  void write_interface(const scene::Scene& scene, const scene::Discretisation& disc,
                       const scene::RunState& state) const;

  std::string directory_;
  VtkSeries series_;
  std::size_t loads_written_ = 0;            ///< records of RunState::loads in loads.csv
  bool loads_started_ = false;               ///< loads.csv holds its header (written whole at the first write)
  int last_vtk_ = -1, last_checkpoint_ = -1; ///< increments written last
  bool checkpoints_stopped_ = false;
};

} // namespace anvil::io
