// A bat by its maker's numbers turned into a profile of round sections. See bat_maker.hpp.
#include "model/bat_maker.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beamimpact {

namespace {

std::string Text(const char *format, double a, double b = 0, double c = 0)
{
  char buf[512];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

// The outer diameter of the rows at x (linear between rows).
PetscReal OuterAt(const std::vector<ProfileRow> &rows, PetscReal x)
{
  for (size_t i = 1; i < rows.size(); ++i)
    if (x <= rows[i].x) {
      const PetscReal s = (x - rows[i - 1].x) / (rows[i].x - rows[i - 1].x);
      return rows[i - 1].D + s * (rows[i].D - rows[i - 1].D);
    }
  return rows.back().D;
}

// The bore from x0 + step to the end: rows at x0 (the inner diameter as it was) and x0 + step
// (d_in), every later row d_in; the rows between them dropped.
void EndBore(std::vector<ProfileRow> *rows, PetscReal x0, PetscReal step, PetscReal d_in)
{
  std::vector<ProfileRow> out;
  PetscReal               d0 = 0;
  for (const ProfileRow &r : *rows) {
    if (r.x < x0) out.push_back(r), d0 = r.d;
    else break;
  }
  ProfileRow a, b;
  a.x = x0, a.D = OuterAt(*rows, x0), a.d = d0;
  b.x = x0 + step, b.D = OuterAt(*rows, x0 + step), b.d = d_in;
  out.push_back(a), out.push_back(b);
  for (const ProfileRow &r : *rows)
    if (r.x > x0 + step) {
      ProfileRow q = r;
      q.d          = d_in;
      out.push_back(q);
    }
  *rows = out;
}

// The positions in order and the diameters and walls within their sections.
bool CheckNumbers(const BatMakerParams &b, PetscReal x3, PetscReal De, PetscReal th, std::string *why)
{
  const PetscReal k = b.knob_length, L = b.length;
  if (!(b.knob_diameter > b.handle_diameter && b.handle_diameter > 0 && b.barrel_diameter > 0 && De > 0)) {
    *why = Text("the diameters must be > 0, the knob's (-bat_knob_diameter %g m) larger than the handle's "
                "(-bat_handle_diameter %g m)",
                b.knob_diameter, b.handle_diameter);
    return false;
  }
  if (!(k > 0 && k + kBatKnobFlare < b.taper_start)) {
    *why = Text("-bat_knob_length %g m and its %g m fillet must end before the taper starts (-bat_taper_start %g m)", k,
                kBatKnobFlare, b.taper_start);
    return false;
  }
  if (!(b.taper_start < b.taper_end && b.taper_end < x3 && x3 <= L)) {
    *why = Text("the taper must start before it ends and end before the barrel's end: -bat_taper_start %g < "
                "-bat_taper_end %g < -bat_end_taper_start (or -bat_length) %g m",
                b.taper_start, b.taper_end, x3);
    if (x3 > L) *why = Text("-bat_end_taper_start %g m must lie within the bat (-bat_length %g m)", x3, L);
    return false;
  }
  if (b.wall_thickness > 0 &&
      !(th < b.handle_diameter / 2 && b.wall_thickness < b.barrel_diameter / 2 && b.wall_thickness < De / 2)) {
    *why = Text("the walls must be thinner than the radii: -bat_handle_wall_thickness %g m < %g m (D_h/2), "
                "-barrel_wall_thickness %g m < half the barrel's and the end's diameters",
                th, b.handle_diameter / 2, b.wall_thickness);
    return false;
  }
  if (b.wall_thickness == 0 && b.handle_wall_thickness > 0) {
    *why = Text("-bat_handle_wall_thickness %g m without -barrel_wall_thickness: a hollow bat needs its barrel's wall "
                "too (a solid bat has none)",
                b.handle_wall_thickness);
    return false;
  }
  return true;
}

// The end cap's inner diameter d_c: the ring over l_c (its first kBatEndStep a linear step from the
// wall's bore d_w) adds the mass m: m/(rho pi/4) = s (2 d_w^2 - d_w d_c - d_c^2)/3 + (l_c - s)(d_w^2 - d_c^2).
bool EndCapBore(const BatMakerParams &b, PetscReal rho, PetscReal d_w, PetscReal *d_c, std::string *why)
{
  const PetscReal s = kBatEndStep, l = b.end_cap_length, A = rho * PETSC_PI / 4;
  if (!(l > 2 * s && l < b.length - b.taper_end)) {
    *why = Text("-bat_end_cap_length %g m must be longer than %g m and lie within the barrel (its %g m after the "
                "taper)",
                l, 2 * s, b.length - b.taper_end);
    return false;
  }
  const PetscReal qa = l - 2 * s / 3, qb = s * d_w / 3, qc = b.end_cap_mass / A - d_w * d_w * (l - s / 3);
  if (!(qc < 0)) {
    *why = Text("-bat_end_cap_mass %g kg does not fit: filling the barrel's last %g m solid adds only %g kg (a longer "
                "-bat_end_cap_length holds more)",
                b.end_cap_mass, l, A * d_w * d_w * (l - s / 3));
    return false;
  }
  *d_c = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  return true;
}

} // namespace

bool BatMakerProfile(const BatMakerParams &b, PetscReal rho, std::vector<ProfileRow> *rows, std::string *why)
{
  const PetscReal L = b.length, x3 = b.end_taper_start > 0 ? b.end_taper_start : L,
                  De = b.end_diameter > 0 ? b.end_diameter : b.barrel_diameter;
  const PetscReal t = b.wall_thickness, th = b.handle_wall_thickness > 0 ? b.handle_wall_thickness : t;
  if (!CheckNumbers(b, x3, De, th, why)) return false;
  const bool      hollow = t > 0;
  const PetscReal dh = hollow ? b.handle_diameter - 2 * th : 0, db = hollow ? b.barrel_diameter - 2 * t : 0,
                  de = hollow ? De - 2 * t : 0;
  auto row           = [](PetscReal x, PetscReal D, PetscReal d) {
    ProfileRow r;
    r.x = x, r.D = D, r.d = d;
    return r;
  };
  rows->clear();
  rows->push_back(row(0, b.knob_diameter, dh));
  rows->push_back(row(b.knob_length, b.knob_diameter, dh));
  rows->push_back(row(b.knob_length + kBatKnobFlare, b.handle_diameter, dh));
  rows->push_back(row(b.taper_start, b.handle_diameter, dh));
  rows->push_back(row(b.taper_end, b.barrel_diameter, db));
  if (x3 < L) rows->push_back(row(x3, b.barrel_diameter, db));
  rows->push_back(row(L, De, de));
  if (b.end_cap_mass > 0) {
    if (!hollow || x3 < L) {
      *why = hollow ? "-bat_end_cap_mass with an end taper (-bat_end_taper_start) is not allowed: the cap thickens the "
                      "wall of a barrel of constant diameter"
                    : Text("-bat_end_cap_mass %g kg on a solid bat is not allowed: a solid barrel has no end cap "
                           "(-barrel_wall_thickness makes the bat hollow; -bat_cup_depth cups a wood bat)",
                           b.end_cap_mass);
      return false;
    }
    PetscReal dc = 0;
    if (!EndCapBore(b, rho, db, &dc, why)) return false;
    EndBore(rows, L - b.end_cap_length, kBatEndStep, dc);
  } else if (b.end_cap_mass < 0) {
    *why = Text("-bat_end_cap_mass %g kg is not allowed: a mass is >= 0", b.end_cap_mass);
    return false;
  }
  if (b.cup_depth > 0) {
    const PetscReal x0 = L - b.cup_depth;
    if (hollow || !(b.cup_diameter > 0 && b.cup_diameter < std::min(De, b.barrel_diameter) && x0 > b.taper_end &&
                    b.cup_depth > 2 * kBatEndStep)) {
      *why = hollow ? "-bat_cup_depth on a hollow bat is not allowed: a cup hollows a solid (wood) bat's end"
                    : Text("-bat_cup_depth %g m with -bat_cup_diameter %g m is not allowed: the cup must be narrower "
                           "than the end (%g m) and lie in the barrel after the tapers",
                           b.cup_depth, b.cup_diameter, De);
      return false;
    }
    EndBore(rows, x0, kBatEndStep, b.cup_diameter);
  }
  return true;
}

PetscReal BatDrop(PetscReal length, PetscReal mass) { return length / kMetresPerInch - mass / kKilogramsPerOunce; }

} // namespace beamimpact
