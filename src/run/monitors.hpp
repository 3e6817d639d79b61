// What a run records while it steps, only when asked (-monitor_*, -snapshot_times,
// -impact_energy_check, -grip; an oblique impact's F_n(t) for the stages after the contact, apart):
// per-step series, snapshots stepped onto exactly, the peaks the
// outcome reports (the segment's kinetic energy, the force on the hands), and the energy-growth
// stop. It writes its own series and peaks; the outcome (run/outcome.hpp) reads them.
#pragma once

#include "run/measures.hpp"

#include <limits>

namespace beamimpact {

class ImpactRecorder {
public:
  ImpactRecorder(Stepper &stepper, const MeasureContext &ctx, const MonitorRequest &mon, const ImpactParams &ip,
                 PetscReal E0, ImpactSeries *series, MonitorPeaks *peaks, ImpactSeries *drive = nullptr);
  // The series at time t (s), and the energy check. Where only the structure's peaks are kept
  // (no series, no energy check, no drive for the stages, nothing tied to the frame) and the
  // stepper samples its state in modes (-ts_type modal), the state is kept as a sample and
  // measured with the others later, many at once (Flush).
  PetscErrorCode Record(PetscReal t);
  // Measures the samples kept since the last flush (the peaks they hold): before the peaks are
  // read, at the end of a run. Collective.
  PetscErrorCode Flush();
  // Every snapshot due by time t.
  PetscErrorCode Snapshots(PetscReal t);
  // The time (s) of the next snapshot; infinity when none is left.
  PetscReal NextSnapshot() const
  {
    return next_ < mon_.snapshot_times.size() ? mon_.snapshot_times[next_] : std::numeric_limits<PetscReal>::infinity();
  }

private:
  Stepper                 &stepper_;
  const MeasureContext    &ctx_;
  const MonitorRequest    &mon_;
  const ImpactParams      &ip_;
  PetscReal                E0_;
  ImpactSeries            *series_;
  ImpactSeries            *drive_; // the stages' F_n(t) (time, the ball's series) at every record, or nullptr
  MonitorPeaks            *peaks_;
  size_t                   next_ = 0;
  std::vector<char>        part_peak_;   // per part slot: its peak is kept
  std::vector<int>         part_series_; // per part slot: its index in series_->keyed (-1: none)
  ContactPhase             last_phase_;  // the contact's phase at the last record (at construction: the contact's own)
  bool                     apart_ = false;        // a part whose peaks the outcome keeps (StructurePart::Peaks)
  bool                     defer_ = false;        // the states may be sampled for the peaks (Record; a drive at once)
  std::vector<StateSample> samples_;              // kept since the last flush
  std::shared_ptr<const BeamModes> sample_modes_; // their basis
  void                             KeepPeaks(const StateMeasures &m, PetscReal t);
};

} // namespace beamimpact
