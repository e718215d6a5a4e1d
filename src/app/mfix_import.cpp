// Translates an MFIX deck into a Bagnold deck (src/app/mfix_import.hpp, docs/import-mfix.md).
// Keyword meanings follow MFIX 21.3's keyword reference; units: SI, or cgs converted to SI.
#include "src/app/mfix_import.hpp"

#include "src/deck/deck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace bagnold::app::mfix {

namespace {

// A real number as TOML writes it: always with a '.' or an exponent.
std::string real_text(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

std::string lower_text(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string vector_text(const std::array<double, 3>& v) {
  return "[" + real_text(v[0]) + ", " + real_text(v[1]) + ", " + real_text(v[2]) + "]";
}

// Factors from the deck's units to SI (1 for an SI deck).
struct Units {
  bool cgs = false;
  double length() const { return cgs ? 0.01 : 1.0; }        // cm -> m
  double velocity() const { return cgs ? 0.01 : 1.0; }      // cm/s -> m/s
  double density() const { return cgs ? 1000.0 : 1.0; }     // g/cm^3 -> kg/m^3
  double pressure() const { return cgs ? 0.1 : 1.0; }       // dyn/cm^2 -> Pa
  double viscosity() const { return cgs ? 0.1 : 1.0; }      // poise -> Pa s
};

// MFIX's frame: direction letters and the face names of each direction in Bagnold's frame.
constexpr const char* mfix_axis = "xyz";
constexpr int bagnold_axis_of[3] = {0, 2, 1};  // MFIX x, y, z -> Bagnold x, z, y
constexpr const char* bagnold_axis_name = "xyz";

// Keywords that only shape MFIX's own output files, logs or parallel layout: they have no effect
// on the solution, so they are noted as comments (Bagnold writes HDF5 snapshots and monitor.csv).
bool output_only(const std::string& keyword) {
  static const std::set<std::string> names = {
      "spx_dt", "full_log", "nlog", "resid_string", "report_mass_balance_dt", "write_vtk_files",
      "time_dependent_filename", "nodesi", "nodesj", "nodesk", "write_dashboard", "out_dt",
      "usr_dt", "batch_wallclock", "term_buffer", "chk_batchq_end", "group_resid",
      "description", "run_name"};
  return names.count(keyword) > 0 || keyword.rfind("monitor_", 0) == 0 ||
         keyword.rfind("vtk_", 0) == 0;
}

class Translator {
 public:
  Translator(const std::vector<Record>& records, const ImportOptions& options)
      : records_(records), options_(options), handled_(records.size(), false) {}

  ImportResult translate();

 private:
  const std::vector<Record>& records_;
  const ImportOptions& options_;
  std::vector<bool> handled_;
  std::vector<Unsupported> unsupported_;
  std::vector<std::string> notes_;  // comments: what was read but has no Bagnold counterpart
  Units units_;
  std::ostringstream out_;

  // The last record of `keyword` with `indices`, marked handled; nullptr when absent.
  const Record* take(const std::string& keyword, const std::vector<int>& indices = {}) {
    const Record* found = nullptr;
    for (std::size_t k = 0; k < records_.size(); ++k)
      if (records_[k].keyword == keyword && records_[k].indices == indices) {
        handled_[k] = true;
        found = &records_[k];
      }
    return found;
  }
  // Every record of `keyword`, marked handled.
  std::vector<const Record*> take_all(const std::string& keyword) {
    std::vector<const Record*> found;
    for (std::size_t k = 0; k < records_.size(); ++k)
      if (records_[k].keyword == keyword) {
        handled_[k] = true;
        found.push_back(&records_[k]);
      }
    return found;
  }
  void refuse(const Record& record, const std::string& why) {
    unsupported_.push_back({record.line, record.name(), why});
  }
  void note(const Record& record, const std::string& why) {
    notes_.push_back(fmt::format("{} = {} (line {}): {}", record.name(),
                                 record.quoted ? "'" + record.value + "'" : record.value,
                                 record.line, why));
  }
  std::optional<double> real(const std::string& keyword, const std::vector<int>& indices,
                             double factor) {
    const Record* record = take(keyword, indices);
    if (!record) return std::nullopt;
    const auto value = as_real(*record);
    if (!value) {
      refuse(*record, "'" + record->value + "' is not a number");
      return std::nullopt;
    }
    return *value * factor;
  }
  // A logical keyword that Bagnold supports with one value only (e.g. energy_eq = .F.).
  void require_logical(const std::string& keyword, bool supported, const std::string& why) {
    for (const Record* r : take_all(keyword)) {
      const auto value = as_logical(*r);
      if (!value) refuse(*r, "'" + r->value + "' is not a logical");
      else if (*value != supported) refuse(*r, why);
    }
  }
  // A string keyword that Bagnold supports with given values only.
  void require_string(const std::string& keyword, const std::set<std::string>& supported,
                      const std::string& why) {
    for (const Record* r : take_all(keyword))
      if (!supported.count(as_upper(*r))) refuse(*r, why);
  }
  std::set<int> region_numbers(const std::string& prefix);

  struct Domain {
    std::array<double, 3> min{}, max{};  // MFIX frame, SI
    std::array<int, 3> cells{};
    bool two_d = false;
  } domain_;

  void run_table();
  void grid_tables();
  std::optional<double> reference_pressure();
  void gas_table();
  void solids_and_models();
  void initial_tables();
  void boundary_tables();
  void numerics_and_output();
  // The box of IC/BC region n in MFIX's frame; false (and refused) when a coordinate is missing.
  bool region_box(const std::string& prefix, int n, std::array<double, 3>& lo,
                  std::array<double, 3>& hi);
  std::array<double, 3> velocity(const std::string& prefix, int n, std::vector<int> extra);
  std::optional<double> reference_pressure_ = std::nullopt;
  bool uses_johnson_jackson_ = false;
};

std::set<int> Translator::region_numbers(const std::string& prefix) {
  std::set<int> numbers;
  for (const auto& r : records_)
    if (r.keyword.rfind(prefix, 0) == 0 && !r.indices.empty()) numbers.insert(r.indices[0]);
  return numbers;
}

ImportResult Translator::translate() {
  // Units first: every other value depends on them.
  if (const Record* r = take("units")) {
    const std::string u = as_upper(*r);
    if (u == "CGS") units_.cgs = true;
    else if (u != "SI") refuse(*r, "units must be 'SI' or 'CGS'");
  }
  // Settings Bagnold supports with MFIX's value only: accepted as they are, refused otherwise.
  require_string("run_type", {"NEW"}, "Bagnold starts a new run here; continue one with `bagnold run --restart`");
  require_string("coordinates", {"CARTESIAN"}, "Bagnold's grid is Cartesian");
  require_logical("energy_eq", false, "Bagnold solves no energy equation (isothermal)");
  require_logical("species_eq", false, "Bagnold has no species equations");
  require_logical("granular_energy", false,
                  "Bagnold's closures take an algebraic granular temperature, no transport equation");
  require_logical("close_packed", true, "Bagnold's closures always limit the packing");
  require_string("solids_model", {"TFM"}, "Bagnold is a two-fluid (TFM) solver only");
  for (const Record* r : take_all("mmax"))
    if (as_integer(*r) != 1) refuse(*r, "Bagnold has one solids phase");
  for (const std::string eq : {"momentum_x_eq", "momentum_y_eq", "momentum_z_eq"})
    require_logical(eq, true, "Bagnold solves every momentum component");

  run_table();
  grid_tables();
  gas_table();
  solids_and_models();
  initial_tables();
  boundary_tables();
  numerics_and_output();

  // What nothing above read: refused (or, with --lenient, a comment), never dropped.
  for (std::size_t k = 0; k < records_.size(); ++k) {
    if (handled_[k]) continue;
    if (output_only(records_[k].keyword))
      note(records_[k], "MFIX output or run control only");
    else
      refuse(records_[k], "no Bagnold equivalent");
  }
  std::stable_sort(unsupported_.begin(), unsupported_.end(),
                   [](const Unsupported& a, const Unsupported& b) { return a.line < b.line; });

  std::string notes;
  if (!notes_.empty()) {
    notes += "\n# Read from the MFIX deck and not carried over (they have no effect on the solution):\n";
    for (const auto& n : notes_) notes += "#   " + n + "\n";
  }
  if (!unsupported_.empty()) {
    notes += "\n# Not expressible in Bagnold, left out (imported with --lenient):\n";
    for (const auto& u : unsupported_)
      notes += fmt::format("#   line {}: {}: {}\n", u.line, u.keyword, u.why);
  }
  std::string header = fmt::format(
      "# Imported from the MFIX deck {} by `bagnold import-mfix` (docs/import-mfix.md).\n"
      "# Frame: MFIX has y vertical, Bagnold z. MFIX (x, y, z) is Bagnold (x, z, y): MFIX's y is\n"
      "# Bagnold's z (vertical), MFIX's z is Bagnold's y; vectors and faces map alike (y- is z-).\n"
      "# Units: {}.\n",
      options_.source_name, units_.cgs ? "the MFIX deck is cgs, converted here to SI" : "SI, as in the MFIX deck");
  return {header + out_.str() + notes, unsupported_};
}

void Translator::run_table() {
  out_ << "\n[run]\n";
  std::string title;
  if (const Record* r = take("run_name")) title = r->value;
  if (const Record* r = take("description")) title += (title.empty() ? "" : ": ") + r->value;
  std::string escaped;
  for (char c : title) {
    if (c == '"' || c == '\\') escaped += '\\';
    escaped += c;
  }
  out_ << "title = \"" << escaped << "\"\n";
  const Record* tstop = take("tstop");
  if (const auto v = tstop ? as_real(*tstop) : std::nullopt)
    out_ << "end_time = " << real_text(*v) << "               # [s] MFIX tstop\n";
  else if (tstop) refuse(*tstop, "not a number");
  const Record* dt = take("dt");
  if (const auto v = dt ? as_real(*dt) : std::nullopt)
    out_ << "dt_initial = " << real_text(*v) << "           # [s] MFIX dt\n";
  else if (dt) refuse(*dt, "not a number (MFIX's steady-state solve: Bagnold is transient only)");
  if (const auto v = real("dt_min", {}, 1.0)) out_ << "dt_min = " << real_text(*v) << "               # [s] MFIX dt_min\n";
  if (const auto v = real("dt_max", {}, 1.0)) out_ << "dt_max = " << real_text(*v) << "               # [s] MFIX dt_max\n";
}

void Translator::grid_tables() {
  static const char* min_key[3] = {"x_min", "y_min", "z_min"};
  static const char* max_key[3] = {"x_max", "y_max", "z_max"};
  static const char* length_key[3] = {"xlength", "ylength", "zlength"};
  static const char* cells_key[3] = {"imax", "jmax", "kmax"};
  if (const Record* r = take("no_k")) {
    const auto v = as_logical(*r);
    if (!v) refuse(*r, "not a logical");
    domain_.two_d = v.value_or(false);
  }
  for (int d = 0; d < 3; ++d) {
    const double lo = real(min_key[d], {}, units_.length()).value_or(0.0);
    const auto hi = real(max_key[d], {}, units_.length());
    const auto length = real(length_key[d], {}, units_.length());
    domain_.min[d] = lo;
    if (hi) domain_.max[d] = *hi;
    else if (length) domain_.max[d] = lo + *length;
    else domain_.max[d] = lo + 1.0;  // refused below unless 2-D in z
    const Record* cells = take(cells_key[d]);
    domain_.cells[d] = cells ? as_integer(*cells).value_or(0) : 0;
    if (d == 2 && domain_.two_d) {
      if (cells && domain_.cells[d] != 1) refuse(*cells, "kmax must be 1 with no_k = .T.");
      domain_.cells[d] = 1;
    } else {
      if (!hi && !length)
        unsupported_.push_back({0, max_key[d], std::string("the domain needs ") + max_key[d] + " or " + length_key[d]});
      if (!cells || domain_.cells[d] < 1)
        unsupported_.push_back({cells ? cells->line : 0, cells_key[d], "a positive number of cells is needed"});
    }
    for (const char* spacing : {"dx", "dy", "dz"})
      if (spacing[1] == mfix_axis[d])
        for (const Record* r : take_all(spacing))
          refuse(*r, "non-uniform MFIX cell sizes: give a uniform grid (Bagnold's grid.*.ratio is geometric)");
  }
  std::vector<std::string> periodic;
  for (int d = 0; d < 3; ++d) {
    if (const Record* r = take(std::string("cyclic_") + mfix_axis[d]))
      if (as_logical(*r).value_or(false)) periodic.push_back(std::string(1, bagnold_axis_name[bagnold_axis_of[d]]));
    if (const Record* r = take(std::string("cyclic_") + mfix_axis[d] + "_pd"))
      if (as_logical(*r).value_or(false)) refuse(*r, "Bagnold's periodic pairs have no pressure drop");
  }
  // Gravity: MFIX gravity_x/y/z, or the magnitude `gravity` along -y; MFIX's default 9.80665.
  const double g0 = real("gravity", {}, units_.velocity()).value_or(9.80665);
  std::array<double, 3> g{0.0, -g0, 0.0};
  bool components = false;
  for (int d = 0; d < 3; ++d)
    if (const auto v = real(std::string("gravity_") + mfix_axis[d], {}, units_.velocity())) {
      if (!components) g = {0.0, 0.0, 0.0};
      components = true;
      g[d] = *v;
    }
  out_ << "\n[physics]\ngravity = " << vector_text(to_bagnold_frame(g))
       << "   # [m/s^2] MFIX gravity" << (components ? "_x/y/z" : "") << ", in Bagnold's frame\n";
  out_ << "\n[grid]\n";
  if (!periodic.empty()) {
    out_ << "periodic = [";
    for (std::size_t k = 0; k < periodic.size(); ++k) out_ << (k ? ", " : "") << '"' << periodic[k] << '"';
    out_ << "]   # MFIX cyclic_*\n";
  }
  for (int b = 0; b < 3; ++b) {
    const int d = b == 0 ? 0 : (b == 1 ? 2 : 1);  // Bagnold x, y, z from MFIX x, z, y
    out_ << "[grid." << bagnold_axis_name[b] << "]          # MFIX " << mfix_axis[d] << "\n";
    out_ << "min = " << real_text(domain_.min[d]) << "\nmax = " << real_text(domain_.max[d])
         << "\ncells = " << domain_.cells[d];
    if (d == 2 && domain_.two_d)
      out_ << "       # MFIX no_k = .T.: one cell across, between free-slip walls";
    out_ << "\n";
  }
}

std::optional<double> Translator::reference_pressure() {
  // Bagnold's gas.reference_pressure is the gas pressure at the top of the domain: the pressure
  // of an opening on the top face, else of the initial region that reaches the top.
  for (int n : region_numbers("bc_")) {
    const Record* type = nullptr;
    for (const auto& r : records_)
      if (r.keyword == "bc_type" && r.indices == std::vector<int>{n}) type = &r;
    if (!type) continue;
    const std::string t = as_upper(*type);
    if (t != "PO" && t != "P_OUTFLOW" && t != "PI" && t != "P_INFLOW") continue;
    std::optional<double> ys, yn, p;
    for (const auto& r : records_) {
      if (r.indices != std::vector<int>{n}) continue;
      if (r.keyword == "bc_y_s") ys = as_real(r);
      if (r.keyword == "bc_y_n") yn = as_real(r);
      if (r.keyword == "bc_p_g") p = as_real(r);
    }
    if (ys && yn && p && *ys == *yn && std::abs(*ys * units_.length() - domain_.max[1]) < 1e-12)
      return *p * units_.pressure();
  }
  for (int n : region_numbers("ic_")) {
    std::optional<double> yn, p;
    for (const auto& r : records_) {
      if (r.indices != std::vector<int>{n}) continue;
      if (r.keyword == "ic_y_n") yn = as_real(r);
      if (r.keyword == "ic_p_g") p = as_real(r);
    }
    if (yn && p && std::abs(*yn * units_.length() - domain_.max[1]) < 1e-12) return *p * units_.pressure();
  }
  return std::nullopt;
}

void Translator::gas_table() {
  out_ << "\n[gas]\n";
  reference_pressure_ = reference_pressure();
  const double p_ref = reference_pressure_.value_or(101325.0);
  if (const auto rho = real("ro_g0", {}, units_.density())) {
    out_ << "density = " << real_text(*rho) << "               # [kg/m^3] MFIX ro_g0\n";
    if (const Record* r = take("mw_avg")) note(*r, "not used: ro_g0 gives a constant density");
  } else if (const Record* mw = take("mw_avg")) {
    // Bagnold's gas is incompressible: MFIX's ideal gas becomes its density at the reference
    // pressure and temperature (t_g0, else 293.15 K), a fair model where pressure varies little.
    const auto molar_mass = as_real(*mw);
    const double temperature = real("t_g0", {}, 1.0).value_or(293.15);
    if (!molar_mass || *molar_mass <= 0.0) {
      refuse(*mw, "not a positive molar mass");
    } else {
      const double density = p_ref * *molar_mass / (8314.462618 * temperature);
      out_ << "density = " << real_text(density) << "   # [kg/m^3] MFIX's ideal gas (mw_avg = "
           << mw->value << ") at the reference pressure " << real_text(p_ref) << " Pa and "
           << real_text(temperature) << " K:\n"
           << "                             # Bagnold's gas has a constant density (docs/import-mfix.md)\n";
    }
  } else {
    unsupported_.push_back({0, "ro_g0", "the gas needs ro_g0 or mw_avg (MFIX's species database is not read)"});
  }
  if (const auto mu = real("mu_g0", {}, units_.viscosity()))
    out_ << "viscosity = " << real_text(*mu) << "           # [Pa s] MFIX mu_g0\n";
  else
    out_ << "viscosity = 1.8e-05           # [Pa s] no mu_g0: air near 293 K (MFIX computes it from T)\n";
  out_ << "reference_pressure = " << real_text(p_ref)
       << "   # [Pa] at the top (MFIX: the top opening's bc_p_g or the top region's ic_p_g);\n"
          "                             # Bagnold starts from a hydrostatic gas pressure below it\n";
}

void Translator::solids_and_models() {
  out_ << "\n[solids]\n";
  if (const auto d = real("d_p0", {1}, units_.length()))
    out_ << "diameter = " << real_text(*d) << "             # [m] MFIX d_p0(1)\n";
  else
    unsupported_.push_back({0, "d_p0(1)", "the solids need a diameter"});
  if (const auto rho = real("ro_s0", {1}, units_.density()))
    out_ << "density = " << real_text(*rho) << "              # [kg/m^3] MFIX ro_s0(1)\n";
  else
    unsupported_.push_back({0, "ro_s0(1)", "the solids need a constant density"});
  if (const auto e = real("c_e", {}, 1.0)) out_ << "restitution = " << real_text(*e) << "            # [-] MFIX c_e\n";

  // Closure: MFIX's algebraic kinetic theory with Schaeffer friction and the plastic pressure
  // is Bagnold's mfix-default.
  out_ << "\n[models.solids_stress]\nmodel = \"mfix-default\"        # MFIX kt_type, friction_model, rdf_type\n";
  // MFIX's ALGEBRAIC is GT_ALGEBRAIC (Syamlal's); LUN_1984 in MFIX solves the granular energy
  // equation, which Bagnold has not: its Lun et al. stresses with the algebraic balance instead.
  std::string kinetic_theory = "syamlal";
  if (const Record* r = take("kt_type")) {
    const std::string kt = as_upper(*r);
    if (kt == "LUN_1984") {
      kinetic_theory = "lun";
      out_ << "# MFIX kt_type = 'LUN_1984' solves a granular energy equation; mfix-default takes Lun et\n"
              "# al. (1984)'s stresses with an algebraic temperature instead (docs/import-mfix.md)\n";
    } else if (kt != "ALGEBRAIC") {
      refuse(*r, "Bagnold's mfix-default has the algebraic kinetic theory only");
    }
  }
  if (const Record* r = take("friction_model"))
    if (as_upper(*r) != "SCHAEFFER") refuse(*r, "mfix-default has Schaeffer's friction only");
  if (const Record* r = take("rdf_type"))
    if (as_upper(*r) != "CARNAHAN_STARLING" && as_upper(*r) != "CARNAHAN-STARLING")
      refuse(*r, "mfix-default has the Carnahan-Starling g0 only");
  out_ << "\n[models.solids_stress.mfix-default]\n";
  out_ << "kinetic_theory = \"" << kinetic_theory << "\"   # MFIX kt_type ('ALGEBRAIC': Syamlal's GT_ALGEBRAIC)\n";
  if (const auto ep = real("ep_star", {}, 1.0))
    out_ << "packed_gas_fraction = " << real_text(*ep) << "   # [-] MFIX ep_star\n";
  else
    unsupported_.push_back({0, "ep_star", "mfix-default needs ep_star (MFIX has no default either)"});
  if (const auto phi = real("phi", {}, 1.0))
    out_ << "internal_friction_angle = " << real_text(*phi) << "   # [deg] MFIX phi\n";

  out_ << "\n[models.drag]\n";
  std::string drag = "syamlal-obrien";
  if (const Record* r = take("drag_type")) {
    const std::string t = as_upper(*r);
    if (t == "GIDASPOW") drag = "gidaspow";
    else if (t == "WEN_YU") drag = "wen-yu";
    else if (t != "SYAM_OBRIEN") refuse(*r, "Bagnold's drag laws: SYAM_OBRIEN, GIDASPOW, WEN_YU");
  }
  out_ << "model = \"" << drag << "\"     # MFIX drag_type (default SYAM_OBRIEN)\n";
  const Record* c1 = take("drag_c1");
  const Record* d1 = take("drag_d1");
  if (drag == "syamlal-obrien") {
    if (c1 || d1) out_ << "[models.drag.syamlal-obrien]\n";
    if (c1) out_ << "c1 = " << c1->value << "                      # MFIX drag_c1\n";
    if (d1) out_ << "d1 = " << d1->value << "                     # MFIX drag_d1\n";
  } else {
    for (const Record* r : {c1, d1})
      if (r) note(*r, "used by MFIX's SYAM_OBRIEN only");
  }
}

bool Translator::region_box(const std::string& prefix, int n, std::array<double, 3>& lo,
                            std::array<double, 3>& hi) {
  static const char* low_suffix[3] = {"x_w", "y_s", "z_b"};
  static const char* high_suffix[3] = {"x_e", "y_n", "z_t"};
  bool ok = true;
  for (int d = 0; d < 3; ++d) {
    const auto a = real(prefix + low_suffix[d], {n}, units_.length());
    const auto b = real(prefix + high_suffix[d], {n}, units_.length());
    if (domain_.two_d && d == 2) {  // a 2-D deck's regions span the one cell across
      lo[d] = domain_.min[d];
      hi[d] = domain_.max[d];
      continue;
    }
    if (!a || !b) ok = false;
    lo[d] = a.value_or(0.0);
    hi[d] = b.value_or(0.0);
  }
  for (const char* index : {"i_w", "i_e", "j_s", "j_n", "k_b", "k_t"})
    for (const Record* r : take_all(prefix + index))
      if (!r->indices.empty() && r->indices[0] == n) {
        refuse(*r, "regions by cell index: give the coordinates instead");
        ok = false;
      } else {
        handled_[r - records_.data()] = false;  // another region's: read there
      }
  return ok;
}

std::array<double, 3> Translator::velocity(const std::string& prefix, int n, std::vector<int> extra) {
  std::vector<int> indices{n};
  indices.insert(indices.end(), extra.begin(), extra.end());
  const std::string phase = extra.empty() ? "_g" : "_s";
  std::array<double, 3> v{};
  const char* component[3] = {"u", "v", "w"};
  for (int d = 0; d < 3; ++d)
    v[d] = real(prefix + component[d] + phase, indices, units_.velocity()).value_or(0.0);
  return to_bagnold_frame(v);
}

void Translator::initial_tables() {
  std::set<int> numbers;
  for (const auto& r : records_)
    if (r.keyword.rfind("ic_", 0) == 0 && !r.indices.empty()) numbers.insert(r.indices[0]);
  for (int n : numbers) {
    std::array<double, 3> lo{}, hi{};
    if (!region_box("ic_", n, lo, hi)) {
      unsupported_.push_back({0, fmt::format("ic_*({})", n), "the initial region needs all six coordinates"});
      continue;
    }
    out_ << fmt::format("\n[[initial]]                     # MFIX IC {}\n", n);
    out_ << "min = " << vector_text(to_bagnold_frame(lo)) << "\nmax = " << vector_text(to_bagnold_frame(hi)) << "\n";
    const auto ep_s = real("ic_ep_s", {n, 1}, 1.0);
    const auto ep_g = real("ic_ep_g", {n}, 1.0);
    if (ep_s || ep_g)
      out_ << "solids_fraction = " << real_text(ep_s ? *ep_s : 1.0 - *ep_g) << "   # MFIX ic_ep_s("
           << n << ",1)" << (ep_s ? "" : " = 1 - ic_ep_g") << "\n";
    out_ << "gas_velocity = " << vector_text(velocity("ic_", n, {})) << "\n";
    out_ << "solids_velocity = " << vector_text(velocity("ic_", n, {1})) << "\n";
    if (const Record* r = take("ic_p_g", {n})) {
      const auto p = as_real(*r);
      if (!p) refuse(*r, "not a number");
      else if (!reference_pressure_ || std::abs(hi[1] - domain_.max[1]) > 1e-12 * (1.0 + std::abs(domain_.max[1])) ||
               std::abs(*p * units_.pressure() - *reference_pressure_) > 1e-9 * *reference_pressure_)
        note(*r, "MFIX starts from this pressure in the region; Bagnold from a hydrostatic "
                 "pressure below gas.reference_pressure");
    }
    for (const char* temperature : {"ic_t_g", "ic_t_s"})
      for (const Record* r : take_all(temperature))
        if (!r->indices.empty() && r->indices[0] == n) note(*r, "isothermal: energy_eq is off");
        else handled_[r - records_.data()] = false;
    if (const Record* r = take("ic_type", {n}))
      if (as_upper(*r) == "PATCH") refuse(*r, "patched ICs (applied later in the run) have no equivalent");
  }
}

void Translator::boundary_tables() {
  std::set<int> numbers;
  for (const auto& r : records_)
    if (r.keyword.rfind("bc_", 0) == 0 && !r.indices.empty()) numbers.insert(r.indices[0]);
  // e_w, phip and phi_w belong to Johnson-Jackson walls: read here, used or noted below.
  const Record* e_w = take("e_w");
  const Record* phip = take("phip");
  const Record* phi_w = take("phi_w");
  for (int n : numbers) {
    const Record* type_record = take("bc_type", {n});
    if (!type_record) {
      unsupported_.push_back({0, fmt::format("bc_type({})", n), "keywords of BC " + std::to_string(n) + " without its bc_type"});
      continue;
    }
    const std::string type = as_upper(*type_record);
    std::array<double, 3> lo{}, hi{};
    if (!region_box("bc_", n, lo, hi)) {
      refuse(*type_record, "the boundary region needs all six coordinates");
      continue;
    }
    // The face: the one direction in which the region is a plane on the domain's boundary.
    int face_axis = -1;
    bool upper = false, flat_twice = false;
    for (int d = 0; d < 3; ++d) {
      if (domain_.two_d && d == 2) continue;
      if (lo[d] != hi[d]) continue;
      if (face_axis >= 0) flat_twice = true;
      face_axis = d;
      upper = std::abs(lo[d] - domain_.max[d]) < 1e-12 * (1.0 + std::abs(domain_.max[d]));
      if (!upper && std::abs(lo[d] - domain_.min[d]) > 1e-12 * (1.0 + std::abs(domain_.min[d]))) face_axis = -2;
    }
    if (face_axis < 0 || flat_twice) {
      refuse(*type_record, "not a plane on a face of the box domain (internal surfaces and obstacles are not imported)");
      continue;
    }
    std::string bagnold_type, extra;
    const Record* jj = take("bc_jj_ps", {n});
    const bool johnson_jackson = jj && as_integer(*jj).value_or(0) == 1;
    if (type == "NSW" || type == "NO_SLIP_WALL" || type == "PSW" || type == "PAR_SLIP_WALL") {
      for (const char* hw : {"bc_hw_g", "bc_hw_s"})
        for (const Record* r : take_all(hw))
          if (!r->indices.empty() && r->indices[0] == n) refuse(*r, "partial-slip walls (a slip length) have no equivalent");
          else handled_[r - records_.data()] = false;
      std::array<double, 3> uw{};
      const char* component[3] = {"bc_uw_g", "bc_vw_g", "bc_ww_g"};
      for (int d = 0; d < 3; ++d) uw[d] = real(component[d], {n}, units_.velocity()).value_or(0.0);
      for (const char* c : {"bc_uw_s", "bc_vw_s", "bc_ww_s"})
        if (const Record* r = take(c, {n, 1})) {
          const auto v = as_real(*r);
          if (!v || *v * units_.velocity() != uw[std::string(c) == "bc_uw_s" ? 0 : (std::string(c) == "bc_vw_s" ? 1 : 2)])
            refuse(*r, "a solids wall velocity other than the gas's");
        }
      const bool moving = uw != std::array<double, 3>{};
      if ((type == "PSW" || type == "PAR_SLIP_WALL") && !johnson_jackson && !moving) {
        refuse(*type_record, "PSW without bc_jj_ps = 1 or a wall velocity has no equivalent");
        continue;
      }
      bagnold_type = moving ? "moving_wall" : "no_slip_wall";
      if (moving) extra += "wall_velocity = " + vector_text(to_bagnold_frame(uw)) + "   # MFIX bc_uw/vw/ww_g\n";
      if (johnson_jackson) {
        uses_johnson_jackson_ = true;
        extra += "solids_wall = \"johnson-jackson\"   # MFIX bc_jj_ps = 1\n";
        if (phip) extra += "specularity = " + phip->value + "   # MFIX phip\n";
        else unsupported_.push_back({jj->line, jj->name(), "Johnson-Jackson walls need phip"});
        if (e_w) extra += "wall_restitution = " + e_w->value + "   # MFIX e_w\n";
        else unsupported_.push_back({jj->line, jj->name(), "Johnson-Jackson walls need e_w"});
      }
    } else if (type == "FSW" || type == "FREE_SLIP_WALL") {
      bagnold_type = "free_slip_wall";
    } else if (type == "PO" || type == "P_OUTFLOW" || type == "PI" || type == "P_INFLOW") {
      bagnold_type = type[1] == 'O' || type == "P_OUTFLOW" ? "pressure_outflow" : "pressure_inflow";
      if (const auto p = real("bc_p_g", {n}, units_.pressure())) {
        extra += "pressure = " + real_text(*p) + "   # [Pa] MFIX bc_p_g\n";
      } else {
        refuse(*type_record, "a pressure boundary needs bc_p_g");
      }
      // MFIX copies the solids pressure into a pressure outflow's cells (set_outflow.f).
      if (bagnold_type == "pressure_outflow")
        extra += "solids_pressure = \"zero-gradient\"   # as MFIX's outflow cells\n";
    } else if (type == "MI" || type == "MASS_INFLOW") {
      bagnold_type = "mass_inflow";
      extra += "gas_velocity = " + vector_text(velocity("bc_", n, {})) + "\n";
      extra += "solids_velocity = " + vector_text(velocity("bc_", n, {1})) + "\n";
      const auto ep_s = real("bc_ep_s", {n, 1}, 1.0);
      const auto ep_g = real("bc_ep_g", {n}, 1.0);
      extra += "solids_fraction = " + real_text(ep_s ? *ep_s : (ep_g ? 1.0 - *ep_g : 0.0)) + "\n";
      if (const Record* r = take("bc_p_g", {n})) note(*r, "a mass inflow's pressure only sets MFIX's ideal-gas density");
      for (const char* flow : {"bc_massflow_g", "bc_volflow_g"})
        if (const Record* r = take(flow, {n})) refuse(*r, "give the inflow velocity instead of a flow rate");
      for (const char* flow : {"bc_massflow_s", "bc_volflow_s"})
        if (const Record* r = take(flow, {n, 1})) refuse(*r, "give the inflow velocity instead of a flow rate");
    } else if (type == "MO" || type == "MASS_OUTFLOW" || type == "OUTFLOW") {
      refuse(*type_record, "Bagnold has no mass outflow: use a pressure outflow (PO)");
      continue;
    } else {
      refuse(*type_record, "unknown boundary type");
      continue;
    }
    if (jj && !johnson_jackson && bagnold_type != "no_slip_wall" && bagnold_type != "moving_wall")
      note(*jj, "used by MFIX on walls only");
    // Bagnold selects boundary cells by their centres, half a cell beyond the face: the box
    // extends one domain length outwards in the face's direction.
    const double length = domain_.max[face_axis] - domain_.min[face_axis];
    if (upper) hi[face_axis] += length;
    else lo[face_axis] -= length;
    const int b = bagnold_axis_of[face_axis];
    out_ << fmt::format("\n[[boundary]]                    # MFIX BC {}: {}\n", n, type);
    out_ << fmt::format("name = \"bc{}_{}\"\ntype = \"{}\"\nface = \"{}{}\"\n", n,
                        lower_text(type),
                        bagnold_type, bagnold_axis_name[b], upper ? '+' : '-');
    out_ << "min = " << vector_text(to_bagnold_frame(lo)) << "\nmax = " << vector_text(to_bagnold_frame(hi)) << "\n" << extra;
    for (const char* temperature : {"bc_t_g", "bc_t_s", "bc_theta_m"})
      for (const Record* r : take_all(temperature))
        if (!r->indices.empty() && r->indices[0] == n) note(*r, "isothermal, algebraic granular temperature");
        else handled_[r - records_.data()] = false;
  }
  if (!uses_johnson_jackson_) {
    for (const Record* r : {e_w, phip, phi_w})
      if (r) note(*r, "used by MFIX only on walls with bc_jj_ps = 1; no wall here has it");
  } else if (phi_w) {
    refuse(*phi_w, "Bagnold's Johnson-Jackson wall has no wall friction angle");
  }
  if (domain_.two_d)
    for (const char* face : {"y-", "y+"})
      out_ << "\n[[boundary]]                    # MFIX no_k = .T.: no walls across the 2-D plane\n"
           << "name = \"plane_" << (face[1] == '-' ? "back" : "front") << "\"\ntype = \"free_slip_wall\"\nface = \"" << face << "\"\n";
  out_ << "\n[geometry]\ndefault_wall = \"no_slip_wall\"   # MFIX: a boundary no BC names is a no-slip wall\n";
}

void Translator::numerics_and_output() {
  out_ << "\n[numerics]\n";
  // MFIX's SET_FLAGS makes every no-slip wall cell beside a flow boundary free-slip in the
  // strain rate (not in the momentum equations); Bagnold's default keeps that wall's shear.
  out_ << "wall_shear_beside_openings = false   # as MFIX's SET_FLAGS (docs/import-mfix.md)\n";
  // MFIX's flow-boundary cells have zero viscosity, which its harmonic edge means carry to every
  // edge of an opening's velocity faces: they feel no wall shear.
  out_ << "shear_on_opening_faces = false   # as MFIX's zero viscosity in flow cells (docs/import-mfix.md)\n";
  // MFIX's SET_OUTFLOW copies the fluid cell's tangential velocities into a PO or PI cell.
  out_ << "copy_velocity_into_openings = true   # as MFIX's SET_OUTFLOW (docs/import-mfix.md)\n";
  // MFIX's SET_OUTFLOW_FLUXES copies the fluid cell's mass fluxes into a PO or PI cell, and its
  // momentum equations convect with them (GET_VCELL_SCFLUX_TERMS and its siblings).
  out_ << "copy_fluxes_into_openings = true   # as MFIX's SET_OUTFLOW_FLUXES (docs/import-mfix.md)\n";
  // MFIX's face and edge viscosities are harmonic means (AVG_H in GET_VCELL_SDIFF_TERMS and its
  // siblings); with Bagnold's arithmetic default the bin's orifice cells against the side walls
  // dilate into the kinetic regime, which MFIX's do not (cases/bin/mfix/README.md).
  out_ << "viscosity_average = \"harmonic\"   # as MFIX's AVG_H (docs/import-mfix.md)\n";
  // A numerics choice, not MFIX's, measured on MFIX's 3-D bin decks: GAMG takes 0.93 (5 mm) and
  // 0.76 (10 mm) of hypre's CPU time for the same rate, and about the same on a 3-D bubbling bed
  // (docs/benchmarks.md, "The pressure preconditioner"); 2-D decks keep hypre.
  // One build serving 20 steps: 0.864 of the CPU time on the 5 mm deck for the same rate.
  if (!domain_.two_d) {
    out_ << "pressure_preconditioner = \"gamg\"   # faster on MFIX's 3-D bin decks (docs/benchmarks.md)\n";
    out_ << "pressure_preconditioner_steps = 20   # faster on MFIX's 3-D bin decks (docs/benchmarks.md)\n";
  }
  // MFIX discretize(n): 0 first-order upwind (the default), 2 Superbee, 6 MUSCL, 7 van Leer,
  // 8 minmod; Bagnold has one scheme for every equation.
  static const std::map<int, std::string> schemes = {
      {0, "upwind"}, {1, "upwind"}, {2, "superbee"}, {6, "muscl"}, {7, "van_leer"}, {8, "minmod"}};
  std::optional<int> scheme;
  bool consistent = true;
  for (const Record* r : take_all("discretize")) {
    const auto s = as_integer(*r);
    if (!s || !schemes.count(*s)) {
      refuse(*r, "Bagnold's schemes: 0 or 1 (upwind), 2 (Superbee), 6 (MUSCL), 7 (van Leer), 8 (minmod)");
      continue;
    }
    if (scheme && schemes.at(*scheme) != schemes.at(*s)) {
      consistent = false;
      refuse(*r, "Bagnold has one convection scheme for every equation");
    }
    if (!scheme) scheme = *s;
  }
  out_ << "convection = \"" << schemes.at(scheme.value_or(0)) << "\"   # MFIX discretize"
       << (scheme ? "" : " (MFIX's default 0, first-order upwind)") << (consistent ? "" : " (the first)") << "\n";
  // MFIX's tol_resid bounds a sum of residuals normalized otherwise (CHECK_CONVERGENCE), so the
  // same number is not the same stopping point. Bagnold's own tolerance is written instead:
  // under it the imported bins discharge as converged runs do, where tol_resid = 1e-3 taken as
  // Bagnold's tolerance accepted steps after one or two outer iterations and drained the 5 mm
  // bin at 87 g/s instead of 230 (docs/import-mfix.md).
  if (const Record* r = take("tol_resid")) {
    if (!as_real(*r)) refuse(*r, "'" + r->value + "' is not a number");
    else note(*r, "MFIX's convergence sum (CHECK_CONVERGENCE), normalized otherwise; numerics.tolerance is Bagnold's own");
  }
  out_ << "tolerance = " << real_text(deck::Numerics{}.tolerance)
       << "   # Bagnold's default, not MFIX tol_resid (docs/import-mfix.md)\n";
  if (const Record* r = take("max_nit")) {
    const auto n = as_integer(*r);
    if (!n || *n < 1) refuse(*r, "not a positive integer");
    else out_ << "max_outer_iterations = " << std::min(*n, 1000) << "   # MFIX max_nit" << (*n > 1000 ? " (Bagnold's limit 1000)" : "") << "\n";
  }
  {
    const Record* r = take("detect_stall");
    const auto stall = r ? as_logical(*r) : std::optional<bool>(true);
    if (!stall) refuse(*r, "'" + r->value + "' is not a logical");
    out_ << "detect_stall = " << (stall.value_or(true) ? "true" : "false") << "   # MFIX detect_stall"
         << (r && stall ? "" : " (MFIX's default .T.)") << "\n";
  }
  if (const auto fac = real("dt_fac", {}, 1.0)) {
    if (*fac <= 0.0 || *fac > 1.0) refuse(*take("dt_fac"), "dt_fac must be in (0, 1]");
    else out_ << "dt_growth = " << real_text(std::clamp(1.0 / *fac, 1.0, 2.0)) << "   # 1/dt_fac (MFIX grows dt by 1/dt_fac)\n";
  }
  // Snapshots serve as both MFIX's restart file and its VTK output: the shortest interval.
  std::optional<double> interval = real("res_dt", {}, 1.0);
  for (const auto& r : records_)
    if (r.keyword == "vtk_dt") {
      const auto v = as_real(r);
      if (v && (!interval || *v < *interval)) interval = *v;
    }
  out_ << "\n[output]\ndirectory = \"runs/" << [&] {
    std::string stem = options_.source_name;
    const auto slash = stem.find_last_of('/');
    if (slash != std::string::npos) stem = stem.substr(slash + 1);
    const auto dot = stem.find_last_of('.');
    return dot == std::string::npos ? stem : stem.substr(0, dot);
  }() << "\"\n";
  if (interval) out_ << "snapshot_interval = " << real_text(*interval) << "   # [s] the shorter of MFIX res_dt and vtk_dt\n";
}

}  // namespace

std::array<double, 3> to_bagnold_frame(const std::array<double, 3>& mfix) {
  return {mfix[0], mfix[2], mfix[1]};
}

ImportResult import_deck(const std::vector<Record>& records, const ImportOptions& options) {
  return Translator(records, options).translate();
}

std::string unsupported_report(const std::string& file, const std::vector<Unsupported>& list) {
  std::string text;
  for (const auto& u : list)
    text += u.line > 0 ? fmt::format("{}:{}: {}: {}\n", file, u.line, u.keyword, u.why)
                       : fmt::format("{}: {}: {}\n", file, u.keyword, u.why);
  return text;
}

}  // namespace bagnold::app::mfix
