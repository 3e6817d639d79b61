// Recording during a run. See monitors.hpp.
#include "run/monitors.hpp"

#include "model/contact.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

// Samples measured at once (Flush): a whole contact of a few hundred steps in one or two matrix
// products (each reads the n x k modes once); 2 n doubles per sample (the 145-node racket: 11 MB).
constexpr size_t kSampleBatch = 256;

ImpactRecorder::ImpactRecorder(Stepper &stepper, const MeasureContext &ctx, const MonitorRequest &mon,
                               const ImpactParams &ip, PetscReal E0, ImpactSeries *series, MonitorPeaks *peaks,
                               ImpactSeries *drive) :
  stepper_(stepper),
  ctx_(ctx),
  mon_(mon),
  ip_(ip),
  E0_(E0),
  series_(series),
  drive_(drive),
  peaks_(peaks),
  last_phase_(ctx.contact ? ctx.contact->phase : ContactPhase::Loading)
{
  series->velocity_at.assign(mon.velocity_at.size(), {});
  series->velocity_at_x = mon.velocity_at;
  for (const PartInstance &p : ctx.sys->parts) // the registered parts' peaks and series, by slot
    for (const PartSlot &slot : p.part->Slots()) {
      const bool asked = slot.own_monitor ? p.part->Monitors(*p.params) : (bool)mon.energy;
      part_peak_.push_back(slot.peak);
      part_series_.push_back(slot.series && asked ? (int)series->keyed.size() : -1);
      if (part_series_.back() >= 0) series->keyed.push_back({slot.name, slot.unit, {}, ""});
    }
  for (const PartInstance &s : ctx.sys->parts) apart_ = apart_ || s.part->Peaks();
  const bool keeps = apart_ || !ctx.sys->face_fields.empty() || !part_peak_.empty(); // else nothing to sample for
  defer_           = keeps && !mon.any() && !ip.energy_check && !ctx.sys->TiedToFrame() && ctx.contact &&
           std::all_of(part_series_.begin(), part_series_.end(), [](int k) { return k < 0; });
}

namespace {

// -monitor_ball's series at a record: the ball, its compression, force and the force's rate. At
// a separation (the phase already Separated, the last record in contact) the rate from inside, on
// the branch the ball left by: the force's end slope there (the linear law's k dc/dt).
void BallSeriesAppend(const StateMeasures &m, const MeasureContext &ctx, ContactPhase last_phase, ImpactSeries *S)
{
  S->ball_y.push_back(m.ball_y);
  S->ball_v.push_back(m.ball_v);
  S->compression.push_back(m.c);
  S->force.push_back(m.force);
  PetscReal rate = m.force_rate;
  if (ctx.contact->phase == ContactPhase::Separated && last_phase != ContactPhase::Separated) {
    ContactState inside = *ctx.contact;
    inside.phase        = last_phase;
    rate                = ContactStiffness(*ctx.ball, inside, m.c) * m.c_rate;
  }
  S->force_rate.push_back(rate);
}

// -monitor_energy's series at a record, each present part's account with a series
// (StructurePart::AccountSeries: the wall's shell_energy, the bed's bed_energy) its own.
void EnergySeriesAppend(const StateMeasures &m, const BeamSystem &sys, ImpactSeries *S)
{
  S->ball_kinetic.push_back(m.ball_kinetic);
  S->ball_stored.push_back(m.ball_stored);
  S->ball_dissipated.push_back(m.ball_work - m.ball_stored);
  S->beam_kinetic.push_back(m.beam_kinetic);
  S->beam_strain.push_back(m.beam_strain);
  for (const PartInstance &s : sys.parts) {
    if (!s.part->AccountSeries()) continue;
    const PetscInt a = StructureAccountOf(*s.part);
    S->account_energy.resize(StructureAccountCount());
    S->account_energy[a].push_back(m.account_energy[a]);
  }
  S->total_energy.push_back(m.total());
  if (sys.Damped()) S->beam_dissipated.push_back(m.beam_dissipated);
}

} // namespace

// The parts' peaks, the barrel wall's, the string bed's and the hands' from a state at time t,
// always (NaN until the first step).
void ImpactRecorder::KeepPeaks(const StateMeasures &m, PetscReal t)
{
  for (size_t k = 0; k < part_peak_.size(); ++k)
    if (part_peak_[k] && !(std::abs(m.part_slot[k]) <= peaks_->part_peak[k]))
      peaks_->part_peak[k] = std::abs(m.part_slot[k]);
  if (apart_ && !(std::abs(m.apart_deflection) <= peaks_->apart_deflection))
    peaks_->apart_deflection = std::abs(m.apart_deflection);
  if (!ctx_.sys->face_fields.empty()) { // a racket's string bed (its fields across the face)
    if (!(m.face_deflection <= peaks_->face_deflection)) peaks_->face_deflection = m.face_deflection;
  }
  for (const PartInstance &s : ctx_.sys->parts) { // each present part's own account
    const PetscInt a = StructureAccountOf(*s.part);
    if (a > 0 && !(m.account_energy[a] <= peaks_->account_energy[a])) peaks_->account_energy[a] = m.account_energy[a];
  }
  if (ctx_.sys->TiedToFrame() && std::abs(m.frame_force) > peaks_->frame_force) { // the hands' peak force
    peaks_->frame_force      = std::abs(m.frame_force);
    peaks_->frame_force_time = t;
  }
}

PetscErrorCode ImpactRecorder::Flush()
{
  SampleRange                r;
  std::vector<PetscReal>     y, v, t;
  std::vector<StateMeasures> m;

  PetscFunctionBeginUser;
  if (samples_.empty()) PetscFunctionReturn(0);
  PetscCheck(stepper_.Modes() == sample_modes_, stepper_.Comm(), PETSC_ERR_PLIB,
             "the stepper's modes changed with %zu samples of the old ones kept", samples_.size());
  PetscCall(stepper_.Expand(samples_, &r, &y, &v));
  for (const StateSample &s : samples_) t.push_back(s.t);
  PetscCall(MeasureStructureStates(stepper_.Comm(), ctx_, r, y, v, t, &m));
  for (size_t q = 0; q < m.size(); ++q) KeepPeaks(m[q], t[q]);
  samples_.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode ImpactRecorder::Record(PetscReal t)
{
  StateMeasures          m;
  std::vector<PetscReal> pv;
  ImpactSeries          &S = *series_;

  PetscFunctionBeginUser;
  const bool face = !ctx_.sys->face_fields.empty(); // a racket's string bed (its fields across the face)
  if (!mon_.any() && !drive_ && !ip_.energy_check && !ctx_.sys->TiedToFrame() && !apart_ && !face && part_peak_.empty())
    PetscFunctionReturn(0);
  if (defer_) { // the peaks: a sample in modes, measured with the others at the next flush
    StateSample s;
    bool        ok;
    PetscCall(stepper_.Sample(&s, &ok));
    if (ok) {
      if (drive_) { // the stages' drive: the ball's measures alone, O(modes), now (the law's state is now's)
        m.ball_y = s.ball_y, m.ball_v = s.ball_v;
        PetscCall(MeasureBall(stepper_, ctx_, &m));
        drive_->time.push_back(t);
        BallSeriesAppend(m, ctx_, last_phase_, drive_);
      }
      if (samples_.empty()) sample_modes_ = stepper_.Modes();
      samples_.push_back(std::move(s));
      if (samples_.size() >= kSampleBatch) PetscCall(Flush());
      last_phase_ = ctx_.contact->phase;
      PetscFunctionReturn(0);
    }
  }
  PetscCall(MeasureState(stepper_, ctx_, &mon_, &m, &pv));
  KeepPeaks(m, t);
  for (size_t k = 0; k < part_series_.size(); ++k)
    if (part_series_[k] >= 0) S.keyed[part_series_[k]].values.push_back(m.part_slot[k]);
  if (ip_.energy_check) {
    const PetscReal growth = (m.total() - E0_) / E0_;
    PetscCheck(growth <= ip_.energy_growth_tol, stepper_.Comm(), PETSC_ERR_NOT_CONVERGED,
               "energy grew by %.3g of the incident kinetic energy at t = %g s %s", (double)growth, (double)t,
               stepper_.EnergyGrowthCause().c_str());
  }
  if (drive_) { // the stages' drive, whatever was asked
    drive_->time.push_back(t);
    BallSeriesAppend(m, ctx_, last_phase_, drive_);
  }
  if (!mon_.any()) {
    last_phase_ = ctx_.contact->phase;
    PetscFunctionReturn(0);
  }
  S.time.push_back(t);
  if (mon_.ball) { BallSeriesAppend(m, ctx_, last_phase_, &S); }
  if (mon_.energy) EnergySeriesAppend(m, *ctx_.sys, &S);
  for (size_t q = 0; q < pv.size(); ++q) S.velocity_at[q].push_back(pv[q]);
  last_phase_ = ctx_.contact->phase;
  if (mon_.segment) {
    S.segment_kinetic.push_back(m.segment_kinetic);
    if ((mon_.segment_until < 0 || t <= mon_.segment_until * (1 + 1e-12)) &&
        m.segment_kinetic > peaks_->segment_kinetic) {
      peaks_->segment_kinetic      = m.segment_kinetic;
      peaks_->segment_kinetic_time = t;
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ImpactRecorder::Snapshots(PetscReal t)
{
  PetscFunctionBeginUser;
  while (next_ < mon_.snapshot_times.size() && mon_.snapshot_times[next_] <= t * (1 + 1e-12) + 1e-15) {
    std::vector<PetscReal> y, u;
    PetscCall(stepper_.GatherDisplacement(&y));
    series_->snapshot_time.push_back(mon_.snapshot_times[next_]);
    series_->snapshot_y.push_back(y);
    const BeamSystem &S   = *ctx_.sys;
    bool              own = false; // a part with a field of its own in the snapshots (asked with no fields)
    for (const PartInstance &s : S.parts) {
      std::vector<PetscReal> values;
      std::vector<PetscInt>  labels;
      PartSnapshotSpec       spec;
      own = own || s.part->Snapshot(s, S, {}, &values, &labels, &spec);
    }
    if (own) PetscCall(stepper_.GatherFields(0, S.fields, &u)); // rank 0: every field of every node
    size_t k = 0; // the parts' own fields (the shell's W_n of each harmonic n, the bed's w - y - z phi)
    for (const PartInstance &s : S.parts) {
      ImpactSeries::PartSnapshots one;
      std::vector<PetscReal>      values;
      if (!s.part->Snapshot(s, S, u, &values, &one.labels, &one.spec)) continue;
      if (k == series_->snapshot_parts.size()) one.part = s.part, series_->snapshot_parts.push_back(std::move(one));
      else series_->snapshot_parts[k].labels = one.labels;
      series_->snapshot_parts[k++].values.push_back(std::move(values));
    }
    ++next_;
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact
