// The impact point check. See impact_point.hpp.
#include "run/impact_point.hpp"

#include "model/oblique.hpp"

#include <cmath>

namespace beamimpact {

bool ImpactOnBed(const BeamParams &beam, PetscReal x, PetscReal z)
{
  if (!beam.strings.On()) return false;
  BedGrid g; // the outline alone
  g.shape = beam.strings.shape, g.a = 0.5 * beam.strings.head_length, g.b = 0.5 * beam.strings.head_width;
  return BedInside(g, x - beam.strings.head_center, z);
}

PetscReal FrameHalfWidth(const BeamParams &beam, PetscReal x, const char **source)
{
  const char  *dummy;
  const char *&what = source ? *source : dummy;
  if (beam.section.source == SectionSource::Profile)
    return what = "the profile's radius there, -beam_profile", RoundSectionRadiusAt(beam.section, x);
  if (beam.section.source == SectionSource::Uniform && beam.input.width > 0)
    return what = "half -beam_width", 0.5 * beam.input.width;
  return what = "half the frame's length: its section (-beam_mass, -beam_EI or -beam_properties) gives no width",
         0.5 * beam.length;
}

ImpactPointWhere ImpactPointLocate(const BeamParams &beam, PetscReal x, PetscReal z)
{
  if (!(x >= 0 && x <= beam.length)) return ImpactPointWhere::OffBeam;
  if (ImpactOnBed(beam, x, z)) return ImpactPointWhere::Movable;
  if (beam.strings.On() && z != 0) return ImpactPointWhere::OffFace;           // off the racket's face
  if (std::abs(z) > FrameHalfWidth(beam, x)) return ImpactPointWhere::OffFace; // off the frame's section
  const std::vector<NodeHold> hold          = BeamNodeHolds(beam);
  auto                        held          = [&](PetscInt i) { return hold[i] != NodeHold::None; };
  const ImpactStencil         st            = GridImpactStencil(beam.nodes, beam.length, x);
  const bool                  on_held       = (st.w > 0 && held(st.j)) && (st.w < 1 ? held(st.j + 1) : true);
  const bool                  on_held_right = st.w == 0 && held(st.j + 1);
  return on_held || on_held_right ? ImpactPointWhere::Held : ImpactPointWhere::Movable;
}

PetscErrorCode ImpactPointCheck(MPI_Comm comm, const BeamParams &beam, PetscReal x, const char *what, PetscReal z)
{
  PetscFunctionBeginUser;
  const ImpactPointWhere where = ImpactPointLocate(beam, x, z);
  PetscCheck(where != ImpactPointWhere::OffFace || !beam.strings.On(), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s with -impact_z %g is not allowed: off the frame's axis the ball must strike the string bed, inside "
             "the head's outline (centre x = %g m, %g x %g m, -head_*)",
             what, (double)z, (double)beam.strings.head_center, (double)beam.strings.head_length,
             (double)beam.strings.head_width);
  const char     *source;
  const PetscReal half = FrameHalfWidth(beam, x, &source);
  PetscCheck(where != ImpactPointWhere::OffFace, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s with -impact_z %g is not allowed: off the frame's section; a frame without a string bed is struck "
             "within its half-width across the face, |z| <= %g m (%s; a racket's head: -strings_frame beam with "
             "-head_width)",
             what, (double)z, (double)half, source);
  PetscCheck(where != ImpactPointWhere::OffBeam, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s is not allowed: the impact point must lie on the beam, 0 <= x <= L = %.12g (m)", what,
             (double)beam.length);
  PetscCheck(!(where == ImpactPointWhere::Held && beam.strings.Held()), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s is not allowed: -strings_frame held holds the whole frame, so the ball must strike the bed, inside "
             "the head's outline (x from 0 to -head_length %g m, the head's centre at %g m)",
             what, (double)beam.strings.head_length, (double)(0.5 * beam.strings.head_length));
  PetscCheck(where != ImpactPointWhere::Held, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s is not allowed: that point is held fixed (a clamped or pinned support or inside -beam_clamp); strike "
             "a point that can move",
             what);
  PetscFunctionReturn(0);
}

PetscErrorCode ImpactAcrossCheck(MPI_Comm comm, const BeamParams &beam, PetscReal z)
{
  PetscFunctionBeginUser;
  PetscCheck(z == 0 || beam.parts.Rolls() || beam.strings.On(), comm, PETSC_ERR_ARG_INCOMP,
             "-impact_z %g is not allowed on a beam that cannot roll: give -beam_torsion (the frame's twist) or a "
             "string bed (-strings_frame)",
             (double)z);
  PetscFunctionReturn(0);
}

} // namespace beamimpact
