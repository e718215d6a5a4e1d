#include "src/deck/load.hpp"

#include <fmt/format.h>
#include <fstream>
#include <map>
#include <set>
#include <span>
#include <sstream>

#include "models/drag/drag_law.hpp"
#include "models/stress/friction_table.hpp"
#include "models/stress/solids_stress.hpp"
#include "models/wall/dense_slip.hpp"
#include "models/wall/johnson_jackson.hpp"
#include "src/deck/sections.hpp"
#include "src/util/closest_match.hpp"

namespace bagnold::deck {

namespace {

const std::vector<std::string> top_level_sections = {
    "extends", "run", "physics", "grid", "geometry", "boundary", "gas", "solids", "models", "initial",
    "pressure_probe", "numerics", "output"};

toml::source_region no_source(const std::string& file) {
  toml::source_region r{};  // value-initialized: line 0 means "no position"
  r.path = std::make_shared<const std::string>(file);
  return r;
}

// ---------------------------------------------------------------------------------------------
// Command-line overrides

struct PathPart {
  std::string name;
  int index = -1;  // element of an array of tables, or -1
};

std::vector<PathPart> split_path(const std::string& path) {
  std::vector<PathPart> parts;
  std::stringstream s(path);
  std::string item;
  while (std::getline(s, item, '.')) {
    PathPart part;
    const auto bracket = item.find('[');
    if (bracket != std::string::npos && item.back() == ']') {
      part.name = item.substr(0, bracket);
      try {
        part.index = std::stoi(item.substr(bracket + 1, item.size() - bracket - 2));
      } catch (const std::exception&) {
        return {};
      }
      if (part.index < 0) return {};
    } else {
      part.name = item;
    }
    if (part.name.empty()) return {};
    parts.push_back(part);
  }
  return parts;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// Applies "a.b.c=value" (spaces around the key and the value are ignored, as in a deck line):
// the value is read as TOML (1e-3, true, [0, 0, -9.81], "text"); a bare word that is not TOML
// is taken as a string, so --set models.solids_stress.model=mkt works.
void apply_override(toml::table& root, const std::string& assignment, Diagnostics& diag) {
  const auto equals = assignment.find('=');
  const std::string origin = "--set " + assignment;
  if (equals == std::string::npos || equals == 0) {
    diag.error(no_source(origin), "", "expected KEY=VALUE, e.g. --set solids.diameter=1e-3");
    return;
  }
  const std::string path = trimmed(assignment.substr(0, equals));
  const std::string text = trimmed(assignment.substr(equals + 1));
  const auto parts = split_path(path);
  if (parts.empty()) {
    diag.error(no_source(origin), path, "not a valid key path (use dotted.names or name[index])");
    return;
  }
  toml::table parsed;
  try {
    parsed = toml::parse("value = " + text, origin);
  } catch (const toml::parse_error&) {
    parsed = toml::table{};
    parsed.insert("value", text);
  }
  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const auto& part = parts[i];
    if (part.index >= 0) {
      auto* array = table->get_as<toml::array>(part.name);
      if (!array || part.index >= static_cast<int>(array->size()) ||
          !(*array)[static_cast<std::size_t>(part.index)].is_table()) {
        diag.error(no_source(origin), path,
                   "the deck has no [[" + part.name + "]] element " + std::to_string(part.index));
        return;
      }
      table = (*array)[static_cast<std::size_t>(part.index)].as_table();
    } else {
      auto* node = table->get(part.name);
      if (!node) {
        table->insert(part.name, toml::table{});
        node = table->get(part.name);
      }
      if (!node->is_table()) {
        diag.error(no_source(origin), path, "'" + part.name + "' is not a table");
        return;
      }
      table = node->as_table();
    }
  }
  if (parts.back().index >= 0) {
    diag.error(no_source(origin), path, "cannot replace a whole array element; set its keys");
    return;
  }
  table->insert_or_assign(parts.back().name, *parsed.get("value"));
  diag.note_override(path, origin);
}

// ---------------------------------------------------------------------------------------------
// Model coefficients: [models.<family>.<model>] tables checked against the registry's specs.

void read_coefficients(const toml::table& table, const std::string& path,
                       const std::vector<models::CoefficientSpec>& specs,
                       models::Coefficients& out, Diagnostics& diag) {
  std::vector<std::string> names;
  for (const auto& spec : specs) names.push_back(spec.name);
  check_unknown_keys(table, path, names, diag);
  for (const auto& spec : specs) {
    const toml::node* node = table.get(spec.name);
    if (!node) continue;
    const std::string key_path = path + "." + spec.name;
    if (std::holds_alternative<double>(spec.default_value)) {
      double x = 0;
      if (!read_value(*node, x) || !std::isfinite(x)) {
        diag.error(node->source(), key_path, "expected a real number [" + spec.unit + "]");
      } else if (x < spec.min || x > spec.max) {
        diag.error(node->source(), key_path,
                   "value " + to_toml_text(x) + " is out of range: expected a real number in [" +
                       to_toml_text(spec.min) + ", " + to_toml_text(spec.max) + "]");
      } else {
        out[spec.name] = x;
      }
    } else {
      std::string s;
      if (!read_value(*node, s)) {
        diag.error(node->source(), key_path, "expected a string, one of: " + join(spec.choices));
      } else if (!spec.choices.empty() &&
                 std::find(spec.choices.begin(), spec.choices.end(), s) == spec.choices.end()) {
        std::string message = "unknown value \"" + s + "\"";
        if (auto guess = closest_match(s, spec.choices)) message += "; did you mean \"" + *guess + "\"?";
        diag.error(node->source(), key_path, message + " (one of: " + join(spec.choices) + ")");
      } else {
        out[spec.name] = s;
      }
    }
  }
}

template <class Base>
void read_model_choice(const toml::table* table, const std::string& path,
                       const Section<ModelChoice>& section, const models::Registry<Base>& registry,
                       bool required, ModelChoice& out, Diagnostics& diag) {
  const auto names = registry.names();
  Section<ModelChoice> with_models = section;
  with_models.also_known = names;
  read_section(table, with_models, path, out, diag);
  // Every model's table is checked, selected or not, so a misspelt constant never hides.
  if (table) {
    for (const auto& entry : registry.entries()) {
      if (const auto* sub = table->get_as<toml::table>(entry.name)) {
        models::Coefficients ignored;
        read_coefficients(*sub, path + "." + entry.name, entry.coefficients,
                          entry.name == out.name ? out.coefficients : ignored, diag);
      }
    }
  }
  const auto it = std::find(names.begin(), names.end(), out.name);
  if (it == names.end() && !required && !(table && table->get("model"))) return;
  if (it == names.end()) {
    const toml::node* node = table ? table->get("model") : nullptr;
    std::string message = "unknown model \"" + out.name + "\"";
    if (auto guess = closest_match(out.name, names)) message += "; did you mean \"" + *guess + "\"?";
    diag.error(node ? node->source() : toml::source_region{}, path + ".model",
               message + " (known: " + join(names) + ")");
    return;
  }
  bool complete = true;
  for (const auto& spec : registry.find(out.name).coefficients)
    if (spec.required && !out.coefficients.contains(spec.name)) {
      const toml::node* node = table ? table->get("model") : nullptr;
      diag.error(node ? node->source() : toml::source_region{}, path + "." + out.name + "." + spec.name,
                 "missing key required by model = \"" + out.name + "\" (a real number [" + spec.unit +
                     "] in [" + to_toml_text(spec.min) + ", " + to_toml_text(spec.max) +
                     "]; it has no default)");
      complete = false;
    }
  if (complete) out.coefficients = models::resolve(registry.find(out.name).coefficients, out.coefficients);
}

// ---------------------------------------------------------------------------------------------
// Sections

const toml::table* subtable(const toml::table& parent, const std::string& name,
                            const std::string& path, Diagnostics& diag) {
  const toml::node* node = parent.get(name);
  if (!node) return nullptr;
  if (!node->is_table()) {
    diag.error(node->source(), path, "expected a table [" + path + "]");
    return nullptr;
  }
  return node->as_table();
}

template <class T>
std::vector<T> read_array_of_tables(const toml::table& parent, const std::string& name,
                                    const std::string& path, const Section<T>& section,
                                    Diagnostics& diag) {
  std::vector<T> out;
  const toml::node* node = parent.get(name);
  if (!node) return out;
  const auto* array = node->as_array();
  if (!array || !array->is_array_of_tables()) {
    diag.error(node->source(), path, "expected an array of tables: [[" + path + "]]");
    return out;
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    T value{};
    read_section((*array)[i].as_table(), section, path + "[" + std::to_string(i) + "]", value, diag);
    out.push_back(value);
  }
  return out;
}

void read_grid(const toml::table& root, Deck& deck, Diagnostics& diag) {
  const toml::table* grid = subtable(root, "grid", "grid", diag);
  if (!grid) {
    diag.error(root.source(), "grid", "missing required table [grid] with [grid.x], [grid.y], [grid.z]");
    return;
  }
  read_section(grid, grid_section(), "grid", deck.grid, diag);
  Axis* axes[] = {&deck.grid.x, &deck.grid.y, &deck.grid.z};
  const char* names[] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d) {
    const std::string path = std::string("grid.") + names[d];
    const toml::table* axis = subtable(*grid, names[d], path, diag);
    read_section(axis, axis_section(), path, *axes[d], diag, grid->source());
    if (axis && !(axes[d]->max > axes[d]->min)) {
      const toml::node* max = axis->get("max");
      diag.error(max ? max->source() : axis->source(), path + ".max",
                 "must be greater than " + path + ".min (" + to_toml_text(axes[d]->min) + ")");
    }
  }
}

// A quadric's matrix has 3 entries (the diagonal) or 9 (row by row); its range is [lower, upper].
void check_quadric(const toml::table& table, const Block& block, const std::string& path,
                   Diagnostics& diag) {
  const toml::node* matrix = table.get("matrix");
  if (matrix && !block.matrix.empty() && block.matrix.size() != 3 && block.matrix.size() != 9)
    diag.error(matrix->source(), path + ".matrix",
               "expected 3 entries (the diagonal of A) or 9 (A row by row), got " +
                   std::to_string(block.matrix.size()));
  const toml::node* range = table.get("range");
  if (range && !block.range.empty() &&
      (block.range.size() != 2 || !(block.range[0] < block.range[1])))
    diag.error(range->source(), path + ".range",
               "expected [lower, upper] with lower < upper, got " + node_text(*range));
}

void check_blocks(const toml::table& root, Deck& deck, Diagnostics& diag) {
  const auto* geometry = root.get_as<toml::table>("geometry");
  const auto* array = geometry ? geometry->get_as<toml::array>("block") : nullptr;
  if (!array) return;
  for (std::size_t i = 0; i < deck.geometry.blocks.size() && i < array->size(); ++i) {
    const auto* table = (*array)[i].as_table();
    const std::string path = "geometry.block[" + std::to_string(i) + "]";
    const auto needed = block_shape_keys(deck.geometry.blocks[i].shape);
    if (needed.empty()) continue;  // bad shape already reported
    const auto optional = block_shape_optional_keys(deck.geometry.blocks[i].shape);
    for (const auto& name : needed)
      if (!table->get(name) && std::find(optional.begin(), optional.end(), name) == optional.end())
        diag.error(table->source(), path + "." + name,
                   "missing key required by shape \"" + deck.geometry.blocks[i].shape + "\"");
    for (const auto& [k, node] : *table) {
      const std::string name(k.str());
      if (name == "shape" || name == "blocks") continue;
      if (std::find(needed.begin(), needed.end(), name) == needed.end())
        diag.error(node.source(), path + "." + name,
                   "does not apply to shape \"" + deck.geometry.blocks[i].shape +
                       "\" (its keys: " + join(needed) + ")");
    }
    if (deck.geometry.blocks[i].shape == "quadric")
      check_quadric(*table, deck.geometry.blocks[i], path, diag);
  }
}

void check_boundaries(const toml::table& root, Deck& deck, Diagnostics& diag) {
  const auto* array = root.get_as<toml::array>("boundary");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < deck.boundaries.size(); ++i) {
    const auto& b = deck.boundaries[i];
    const auto* table = array ? (*array)[i].as_table() : nullptr;
    const toml::source_region where = table ? table->source() : toml::source_region{};
    const std::string path = "boundary[" + std::to_string(i) + "]";
    if (!seen.insert(b.name).second)
      diag.error(where, path + ".name", "duplicate boundary name \"" + b.name + "\"");
    if (b.face.size() == 2) {
      const int direction = b.face[0] - 'x';
      if (deck.grid.is_periodic(direction))
        diag.error(where, path + ".face",
                   "face " + b.face + " is periodic (grid.periodic); it has no boundary cells");
    }
  }
}

// The solids wall condition of each [[boundary]]: only on no_slip_wall / moving_wall regions,
// with exactly the parameters its law takes, and within the law's limits (models/wall/).
void check_solids_walls(const toml::table& root, const Deck& deck, Diagnostics& diag) {
  const auto* array = root.get_as<toml::array>("boundary");
  if (!array) return;
  const std::vector<std::pair<std::string, std::string>> parameters = {
      {"specularity", "johnson-jackson"}, {"wall_restitution", "johnson-jackson"},
      {"wall_friction", "dense-slip"}};
  for (std::size_t i = 0; i < deck.boundaries.size() && i < array->size(); ++i) {
    const auto& b = deck.boundaries[i];
    const auto* table = (*array)[i].as_table();
    if (!table) continue;
    const std::string path = "boundary[" + std::to_string(i) + "]";
    auto where = [&](const std::string& name) {
      const toml::node* node = table->get(name);
      return node ? node->source() : table->source();
    };
    const bool wall = b.type == "no_slip_wall" || b.type == "moving_wall";
    // The resolved text (bagnold run's log) writes every key: the defaults must load again.
    if (b.solids_wall != "no-slip" && !wall) {
      diag.error(where("solids_wall"), path + ".solids_wall",
                 "applies to type = \"no_slip_wall\" or \"moving_wall\" only, this region is \"" +
                     b.type + "\"" +
                     (b.type == "free_slip_wall" ? " (free slip for both phases already)" : ""));
      continue;
    }
    for (const auto& [name, law] : parameters) {
      const double value = name == "specularity"        ? b.specularity
                           : name == "wall_restitution" ? b.wall_restitution
                                                        : b.wall_friction;
      if (table->get(name) && b.solids_wall != law && value != 0.0)
        diag.error(where(name), path + "." + name,
                   "applies only to solids_wall = \"" + law + "\" (this region has \"" +
                       b.solids_wall + "\")");
      else if (!table->get(name) && b.solids_wall == law)
        diag.error(table->source(), path + "." + name,
                   "missing key required by solids_wall = \"" + law + "\" (a real number)");
    }
    if (!deck.solids.enabled) continue;
    const auto& material = deck.solids.material;
    if (b.solids_wall == "dense-slip" && table->get("wall_friction")) {
      try {
        const models::wall::DenseSlip check(material, {.wall_friction = b.wall_friction},
                                            models::chialvo2012::yield_stress_ratio(material.friction));
      } catch (const std::invalid_argument& e) {
        const bool wall_side = b.wall_friction < models::wall::chialvo_slip::critical_wall_friction;
        diag.error(wall_side ? where("wall_friction") : where("solids_wall"),
                   path + (wall_side ? ".wall_friction" : ".solids_wall"),
                   std::string("dense-slip: ") + e.what() + (wall_side ? "" : " (solids.friction)"));
      }
    }
    if (b.solids_wall == "johnson-jackson" && table->get("wall_restitution") &&
        b.wall_restitution >= 1.0 && deck.solids.momentum) {
      bool has_temperature = true;
      try {
        has_temperature = models::stress_registry()
                              .create(deck.models.solids_stress.name,
                                      deck.models.solids_stress.coefficients)
                              ->defines_temperature();
      } catch (const std::exception&) {
        // An unknown closure is reported where it is named.
      }
      if (!has_temperature)
        diag.error(where("wall_restitution"), path + ".wall_restitution",
                   "expected < 1 with the closure \"" + deck.models.solids_stress.name +
                       "\", which has no granular temperature: the wall temperature "
                       "(2/3) φ' |u_slip|²/(1 − e_w²) needs e_w < 1");
    }
  }
}

void check_time_stepping(const toml::table& root, Deck& deck, Diagnostics& diag) {
  const auto& r = deck.run;
  if (!(r.dt_min <= r.dt_initial && r.dt_initial <= r.dt_max)) {
    const auto* run = root.get_as<toml::table>("run");
    diag.error(run ? run->source() : root.source(), "run",
               "expected dt_min <= dt_initial <= dt_max, got " + to_toml_text(r.dt_min) +
                   ", " + to_toml_text(r.dt_initial) + ", " + to_toml_text(r.dt_max));
  }
  const auto& n = deck.numerics;
  if (n.hard_outer_iterations > 0 && n.hard_outer_iterations <= n.easy_outer_iterations) {
    const auto* numerics = root.get_as<toml::table>("numerics");
    diag.error(numerics ? numerics->source() : root.source(), "numerics.hard_outer_iterations",
               "expected 0 or more than easy_outer_iterations (" +
                   std::to_string(n.easy_outer_iterations) + "), got " +
                   std::to_string(n.hard_outer_iterations) +
                   ": dt would grow and shrink on the same step");
  }
}

// numerics.partition_weights = "layers" cuts along gravity, which must act along one axis, and
// does not depend on the state, so there is nothing to repartition.
void check_partition(const toml::table& root, const Deck& deck, Diagnostics& diag) {
  const auto* numerics = root.get_as<toml::table>("numerics");
  if (!numerics || deck.numerics.partition_weights != "layers") return;
  const toml::node* node = numerics->get("partition_weights");
  if (deck.physics.gravity_axis() < 0)
    diag.error(node->source(), "numerics.partition_weights",
               "partition_weights = \"layers\" needs gravity along one axis (physics.gravity has " +
                   to_toml_text(deck.physics.gravity) + "); expected cells, work or phases");
  if (deck.numerics.repartition_imbalance > 0.0) {
    const toml::node* other = numerics->get("repartition_imbalance");
    diag.error(other ? other->source() : numerics->source(), "numerics.repartition_imbalance",
               "expected 0 with partition_weights = \"layers\" (a partition by layers does not "
               "depend on the state), got " + to_toml_text(deck.numerics.repartition_imbalance));
  }
}

// The selected closure's own limits on the material (the kinetic models need e < 1, ...): found
// by evaluating it once, at ε_s = 0.3 and γ̇ = 1/s, so `check` refuses what `run` would.
void check_closure_material(const toml::table* solids, const Deck& deck, Diagnostics& diag) {
  if (!deck.solids.enabled || !deck.solids.momentum || !diag.ok()) return;
  const auto& choice = deck.models.solids_stress;
  try {
    const auto model = models::stress_registry().create(choice.name, choice.coefficients);
    const double phi = 0.3, rate = 1.0, divergence = 0.0;
    double p = 0, dp = 0, mu = 0, lambda = 0, theta = 0;
    models::SolidsStress out{std::span(&p, 1), std::span(&dp, 1), std::span(&mu, 1),
                             std::span(&lambda, 1), std::span(&theta, 1)};
    model->evaluate(deck.solids.material,
                    {std::span(&phi, 1), std::span(&rate, 1), std::span(&divergence, 1)}, out);
  } catch (const std::invalid_argument& e) {
    diag.error(solids ? solids->source() : toml::source_region{}, "solids",
               std::string(e.what()) + " (models.solids_stress.model = \"" + choice.name + "\")");
  }
}

// Each [[initial]] region's ε_s at most the selected closure's packing limit φ_max for the
// deck's material (SolidsStressModel::packing_limit: φ_c(μ) of App. A Table I for the kinetic
// models and the rheologies, 1 − ε_g* for the plastic-pressure closures): a fill above it
// starts compressed past jamming, where the closures cap or blow up. Only where the closure is
// used (solids that move); 1e-12 absorbs the rounding of a limit written as 1 − ε_g*.
void check_initial_packing(const toml::table& root, const Deck& deck, Diagnostics& diag) {
  if (!deck.solids.enabled || !deck.solids.momentum || deck.initial.empty()) return;
  const auto& choice = deck.models.solids_stress;
  std::unique_ptr<models::SolidsStressModel> model;
  try {
    model = models::stress_registry().create(choice.name, choice.coefficients);
  } catch (const std::exception&) {
    return;  // an unknown closure or bad coefficients are reported where they are named
  }
  const double limit = model->packing_limit(deck.solids.material);
  // The limit as a reader writes it: 1 − ε_g* = 0.58, not its binary neighbour 0.58000000000000007.
  const std::string limit_text = fmt::format("{:.12g}", limit);
  const auto* array = root.get_as<toml::array>("initial");
  for (std::size_t i = 0; i < deck.initial.size(); ++i) {
    const double fraction = deck.initial[i].solids_fraction;
    if (!(fraction > limit + 1e-12)) continue;
    const auto* table = array && i < array->size() ? (*array)[i].as_table() : nullptr;
    const toml::node* node = table ? table->get("solids_fraction") : nullptr;
    diag.error(node ? node->source() : table ? table->source() : root.source(),
               "initial[" + std::to_string(i) + "].solids_fraction",
               "value " + to_toml_text(fraction) + " is above the packing limit " +
                   limit_text + " of the closure models.solids_stress.model = \"" +
                   choice.name + "\" for the deck's [solids]: expected at most " +
                   limit_text + " (docs/models.md gives each closure's limit)");
  }
}

// Options that work layer by layer across gravity (gas.initial_pressure = bed-weight, a probe's
// average = layer) need gravity along one axis that is not periodic.
void check_layered(const toml::node* node, const std::string& path, const std::string& what,
                   const Deck& deck, Diagnostics& diag) {
  const int axis = deck.physics.gravity_axis();
  if (axis < 0)
    diag.error(node->source(), path,
               what + " needs gravity along one axis (physics.gravity has " +
                   to_toml_text(deck.physics.gravity) + ")");
  else if (deck.grid.is_periodic(axis))
    diag.error(node->source(), path,
               what + " needs the axis of gravity (" + std::string(1, "xyz"[axis]) +
                   ") not periodic (grid.periodic)");
}

void check_initial_pressure(const toml::table& root, const Deck& deck, Diagnostics& diag) {
  const auto* gas = root.get_as<toml::table>("gas");
  const toml::node* node = gas ? gas->get("initial_pressure") : nullptr;
  if (node && deck.gas.initial_pressure == "bed-weight")
    check_layered(node, "gas.initial_pressure", "initial_pressure = \"bed-weight\"", deck, diag);
}

void check_pressure_probes(const toml::table& root, const Deck& deck, Diagnostics& diag) {
  const auto* array = root.get_as<toml::array>("pressure_probe");
  std::set<std::string> seen;
  for (std::size_t i = 0; array && i < deck.pressure_probes.size() && i < array->size(); ++i) {
    const auto& probe = deck.pressure_probes[i];
    const auto* table = (*array)[i].as_table();
    const std::string path = "pressure_probe[" + std::to_string(i) + "]";
    if (!seen.insert(probe.name).second)
      diag.error(table->source(), path + ".name", "duplicate pressure probe name \"" + probe.name + "\"");
    if (probe.average == "layer") {
      const toml::node* average = table->get("average");
      check_layered(average ? average : table, path + ".average",
                    "average = \"layer\" (the default)", deck, diag);
    }
  }
}

void read_material_and_models(const toml::table& root, Deck& deck, Diagnostics& diag) {
  const toml::table* solids = subtable(root, "solids", "solids", diag);
  read_section(solids, solids_section(), "solids", deck.solids.material, diag);
  read_section(solids, solids_switch_section(), "solids", deck.solids, diag, {}, false);
  const toml::table* models_table = subtable(root, "models", "models", diag);
  if (models_table) check_unknown_keys(*models_table, "models", {"solids_stress", "drag"}, diag);
  const toml::table* stress =
      models_table ? subtable(*models_table, "solids_stress", "models.solids_stress", diag) : nullptr;
  // Without solids the closure is not used: its name is checked only when given.
  read_model_choice(stress, "models.solids_stress", solids_stress_section(),
                    models::stress_registry(), deck.solids.enabled, deck.models.solids_stress, diag);
  const toml::table* drag =
      models_table ? subtable(*models_table, "drag", "models.drag", diag) : nullptr;
  read_model_choice(drag, "models.drag", drag_section(), models::drag_registry(),
                    deck.solids.enabled && deck.gas.enabled, deck.models.drag, diag);
  check_closure_material(solids, deck, diag);
}

void read_all(const toml::table& root, Deck& deck, Diagnostics& diag) {
  check_unknown_keys(root, "", top_level_sections, diag);
  const toml::table* run = subtable(root, "run", "run", diag);
  read_section(run, run_section(), "run", deck.run, diag, root.source());
  read_section(subtable(root, "physics", "physics", diag), physics_section(), "physics",
               deck.physics, diag);
  read_grid(root, deck, diag);
  const toml::table* geometry = subtable(root, "geometry", "geometry", diag);
  read_section(geometry, geometry_section(), "geometry", deck.geometry, diag);
  if (geometry)
    deck.geometry.blocks =
        read_array_of_tables(*geometry, "block", "geometry.block", block_section(), diag);
  check_blocks(root, deck, diag);
  deck.boundaries = read_array_of_tables(root, "boundary", "boundary", boundary_section(), diag);
  check_boundaries(root, deck, diag);
  read_section(subtable(root, "gas", "gas", diag), gas_section(), "gas", deck.gas, diag);
  read_material_and_models(root, deck, diag);
  check_solids_walls(root, deck, diag);
  deck.initial = read_array_of_tables(root, "initial", "initial", initial_section(), diag);
  check_initial_packing(root, deck, diag);
  check_initial_pressure(root, deck, diag);
  deck.pressure_probes = read_array_of_tables(root, "pressure_probe", "pressure_probe",
                                              pressure_probe_section(), diag);
  check_pressure_probes(root, deck, diag);
  read_section(subtable(root, "numerics", "numerics", diag), numerics_section(), "numerics",
               deck.numerics, diag);
  check_partition(root, deck, diag);
  read_section(subtable(root, "output", "output", diag), output_section(), "output", deck.output,
               diag, root.source());
  check_time_stepping(root, deck, diag);
}

std::optional<toml::table> parse(const std::string& text, const std::string& source_name,
                                 Diagnostics& diag) {
  try {
    return toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    diag.error(e.source(), "", "TOML syntax error: " + std::string(e.description()));
    return std::nullopt;
  }
}

std::string read_file(const std::string& path);

// Overlays `top` on `base`: tables merge key by key, anything else (values, arrays, arrays of
// tables) replaces what the base had. Nodes are moved, not copied: toml++ keeps a node's source
// position on a move only, and errors in the extending deck must name its file and line.
void overlay(toml::table& base, toml::table&& top) {
  for (auto&& [k, node] : top) {
    auto* existing = base.get(k.str());
    if (existing && existing->is_table() && node.is_table()) {
      overlay(*existing->as_table(), std::move(*node.as_table()));
    } else {
      base.insert_or_assign(k, std::move(node));
    }
  }
}

// `extends = "base.toml"` (relative to the deck's folder): the deck is the base deck with this
// file's keys laid over it, so grid rungs and model variants share one deck.
std::optional<toml::table> resolve_extends(toml::table deck, const std::string& source_name,
                                           Diagnostics& diag, int depth) {
  const toml::node* extends = deck.get("extends");
  if (!extends) return deck;
  const auto base_name = extends->value<std::string>();
  if (!base_name) {
    diag.error(extends->source(), "extends", "expected a string: the path of a base deck");
    return std::nullopt;
  }
  if (depth > 8) {
    diag.error(extends->source(), "extends", "more than 8 levels of extends (a cycle?)");
    return std::nullopt;
  }
  const auto slash = source_name.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : source_name.substr(0, slash + 1);
  const std::string base_path = (*base_name)[0] == '/' ? *base_name : folder + *base_name;
  std::string text;
  try {
    text = read_file(base_path);
  } catch (const DeckError&) {
    diag.error(extends->source(), "extends", "cannot open the base deck '" + base_path + "'");
    return std::nullopt;
  }
  toml::table base;
  try {
    base = toml::parse(text, base_path);
  } catch (const toml::parse_error& e) {
    diag.error(e.source(), "", "TOML syntax error: " + std::string(e.description()));
    return std::nullopt;
  }
  auto resolved_base = resolve_extends(std::move(base), base_path, diag, depth + 1);
  if (!resolved_base) return std::nullopt;
  deck.erase("extends");
  overlay(*resolved_base, std::move(deck));
  return resolved_base;
}

// Every table, array element and key of `table` into `out` under its dotted path, for the
// checks made after loading (Deck::origins).
void record_origins(const toml::table& table, const std::string& path, const Diagnostics& diag,
                    std::map<std::string, Origin>& out) {
  for (auto&& [k, node] : table) {
    const std::string key = path.empty() ? std::string(k.str()) : path + "." + std::string(k.str());
    out[key] = diag.origin(node.source(), key);
    if (const auto* sub = node.as_table()) {
      record_origins(*sub, key, diag, out);
    } else if (const auto* array = node.as_array(); array && array->is_array_of_tables()) {
      for (std::size_t i = 0; i < array->size(); ++i) {
        const std::string element = key + "[" + std::to_string(i) + "]";
        out[element] = diag.origin((*array)[i].source(), element);
        record_origins(*(*array)[i].as_table(), element, diag, out);
      }
    }
  }
}

enum class Scope { whole_deck, material_and_models };

Deck load(const std::string& text, const std::string& source_name,
          const std::vector<std::string>& overrides, Scope scope) {
  Diagnostics diag;
  auto root = parse(text, source_name, diag);
  if (root) root = resolve_extends(std::move(*root), source_name, diag, 0);
  if (!root) throw DeckError(diag);
  for (const auto& o : overrides) apply_override(*root, o, diag);
  Deck deck;
  deck.source = source_name;
  if (scope == Scope::whole_deck) {
    read_all(*root, deck, diag);
    record_origins(*root, "", diag, deck.origins);
  } else {
    read_material_and_models(*root, deck, diag);
  }
  if (!diag.ok()) throw DeckError(diag);
  return deck;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    Diagnostics diag;
    diag.error(no_source(path), "", "cannot open the deck file for reading");
    throw DeckError(diag);
  }
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string show_coefficients(const models::Coefficients& c) {
  std::string out;
  for (const auto& [name, value] : c)
    out += name + " = " +
           (std::holds_alternative<double>(value) ? to_toml_text(std::get<double>(value))
                                                  : to_toml_text(std::get<std::string>(value))) +
           "\n";
  return out;
}

}  // namespace

Deck load_deck(const std::string& path, const std::vector<std::string>& overrides) {
  return load(read_file(path), path, overrides, Scope::whole_deck);
}

bool overrides_key(const std::vector<std::string>& overrides, const std::string& key) {
  for (const auto& o : overrides)
    if (const auto equals = o.find('='); equals != std::string::npos && trimmed(o.substr(0, equals)) == key)
      return true;
  return false;
}

Deck load_deck_text(const std::string& text, const std::string& source_name,
                    const std::vector<std::string>& overrides) {
  return load(text, source_name, overrides, Scope::whole_deck);
}

Deck load_material_and_models(const std::string& path_or_empty,
                              const std::vector<std::string>& overrides) {
  const std::string text = path_or_empty.empty() ? std::string() : read_file(path_or_empty);
  return load(text, path_or_empty.empty() ? "--set" : path_or_empty, overrides,
              Scope::material_and_models);
}

std::string resolved_text(const Deck& d) {
  std::ostringstream s;
  s << "# Resolved configuration of " << d.source << " (defaults filled, overrides applied)\n";
  s << "\n[run]\n" << show_section(run_section(), d.run);
  s << "\n[physics]\n" << show_section(physics_section(), d.physics);
  s << "\n[grid]\n" << show_section(grid_section(), d.grid);
  const Axis* axes[] = {&d.grid.x, &d.grid.y, &d.grid.z};
  for (int a = 0; a < 3; ++a)
    s << "\n[grid." << "xyz"[a] << "]\n" << show_section(axis_section(), *axes[a]);
  s << "\n[geometry]\n" << show_section(geometry_section(), d.geometry);
  for (const auto& b : d.geometry.blocks) {
    s << "\n[[geometry.block]]\nshape = " << to_toml_text(b.shape)
      << "\nblocks = " << to_toml_text(b.blocks) << "\n";
    for (const auto& k : block_section().keys)
      for (const auto& name : block_shape_keys(b.shape))
        if (k.info.name == name) s << name << " = " << k.show(b) << "  # [" << k.info.unit << "]\n";
  }
  for (const auto& b : d.boundaries) s << "\n[[boundary]]\n" << show_section(boundary_section(), b);
  s << "\n[gas]\n" << show_section(gas_section(), d.gas);
  s << "\n[solids]\n"
    << show_section(solids_switch_section(), d.solids)
    << show_section(solids_section(), d.solids.material);
  s << "\n[models.solids_stress]\n" << show_section(solids_stress_section(), d.models.solids_stress);
  s << "\n[models.solids_stress." << d.models.solids_stress.name << "]\n"
    << show_coefficients(d.models.solids_stress.coefficients);
  s << "\n[models.drag]\n" << show_section(drag_section(), d.models.drag);
  s << "\n[models.drag." << d.models.drag.name << "]\n" << show_coefficients(d.models.drag.coefficients);
  for (const auto& r : d.initial) s << "\n[[initial]]\n" << show_section(initial_section(), r);
  for (const auto& p : d.pressure_probes)
    s << "\n[[pressure_probe]]\n" << show_section(pressure_probe_section(), p);
  s << "\n[numerics]\n" << show_section(numerics_section(), d.numerics);
  s << "\n[output]\n" << show_section(output_section(), d.output);
  return s.str();
}

namespace {
std::string escape_cell(std::string text) {
  std::string out;
  for (char c : text) out += (c == '|') ? std::string("\\|") : std::string(1, c);
  return out;
}

void reference_table(std::ostringstream& s, const std::string& heading,
                     const std::vector<KeyInfo>& keys) {
  s << "\n## " << heading << "\n\n";
  s << "| key | type | unit | default | allowed | description |\n";
  s << "| --- | --- | --- | --- | --- | --- |\n";
  for (const auto& k : keys)
    s << "| `" << k.name << "` | " << k.type << " | " << (k.unit.empty() ? "" : k.unit) << " | "
      << (k.required ? std::string("**required**") : escape_cell(k.default_text)) << " | "
      << escape_cell(k.range) << " | " << escape_cell(k.doc) << " |\n";
}

std::vector<KeyInfo> coefficient_infos(const std::vector<models::CoefficientSpec>& specs) {
  std::vector<KeyInfo> keys;
  for (const auto& c : specs) {
    KeyInfo k;
    k.name = c.name;
    k.unit = c.unit;
    k.doc = c.doc;
    if (std::holds_alternative<double>(c.default_value)) {
      k.type = "a real number";
      k.default_text = c.required ? "required" : to_toml_text(std::get<double>(c.default_value));
      k.range = "in [" + to_toml_text(c.min) + ", " + to_toml_text(c.max) + "]";
    } else {
      k.type = "a string";
      k.default_text = to_toml_text(std::get<std::string>(c.default_value));
      k.range = "one of: " + join(c.choices);
    }
    keys.push_back(k);
  }
  return keys;
}

// How blocks and regions select cells (src/grid/cell_flags.hpp, src/run/initial_state.hpp) and
// what check refuses of them (src/app/preflight.hpp), for the key reference.
const char* const region_selection_markdown = R"(
## How regions select cells

Every block and region selects whole cells by their centres (walls are staircases at the grid
scale); a box includes its faces.

- `[[geometry.block]]` makes solid each domain cell whose centre lies inside its shape
  (`blocks = "inside"`) or outside it (`blocks = "outside"`; for a cylinder or cone, around it
  between its end planes; for a quadric, where f ≥ 0 within its range). Blocked cells next to fluid become boundary cells; the others are not
  stored.
- `[[boundary]]` selects boundary cells: the layer of cells just outside each domain face that is
  not periodic (one cell thick, edges and corners included), and the blocked cells next to fluid
  (`face = "internal"`). A region takes the boundary cells of its `face` whose centres lie in its
  box [`min`, `max`]. **The centres of a domain face's boundary cells lie half a cell beyond the
  face** (at z = −Δz/2 below a floor at z = 0), so a box on a domain face must reach past the face:
  `min = [0.0, 0.0, -1.0]`, `max = [0.01, 0.04, 0.0]` selects a 1 cm strip of such a floor, and
  `min = [0.0, 0.0, 0.0]` none of it. A cell that several regions select belongs to the first one
  listed (first wins); cells that no region selects belong to the implicit region `walls`
  (`geometry.default_wall`).
- `[[initial]]` sets the fluid cells whose centres lie in its box; a cell that several regions
  select is set by the last one listed (later wins). Cells that no region selects start with no
  solids and at rest.

`bagnold check` prints each block's and region's cells and each initial region's solids mass
(ρ_s ε_s V over the cells it sets, in kg), notes every pair of boundary regions and every pair of
initial regions that select the same cells (with their number and which region gets them), and
refuses, with exit code 2 and the line of the table or key:

- a block that blocks no cell;
- a boundary region that selects no cell, or all of whose cells belong to earlier regions;
- an initial region that selects no cell;
- an initial `solids_fraction` above the selected closure's packing limit for the deck's
  material (docs/models.md, "Packing limit and wall g0"), where the solids move
  (`solids.momentum = true`);
- a grid whose estimated memory is more than the machine has, at the largest axis's `cells`
  (docs/reliability.md, "Memory estimate").

`bagnold run` refuses the same before anything runs. An error caused by a `--set` names the
`--set` argument instead of the deck's line.
)";

// What a pressure probe measures (src/run/pressure_probe.hpp), for the key reference.
const char* const pressure_probe_markdown = R"(
Each probe adds the column `dp_<name>` [Pa] to monitor.csv: p_g at `lower` minus p_g at `upper`,
after every step. With `average = "layer"` each end is the mean gas pressure of the layer of
cells across gravity that holds the point (every fluid cell of that layer, on whichever rank it
is, weighted by its area across gravity); with `average = "cell"` it is the gas pressure of the
one cell that holds the point. A point on a face between two cells belongs to the upper cell (the
last cell at the domain's upper end). `bagnold check` refuses a point outside the domain, a
`cell` probe whose point lies in a blocked cell and a `layer` probe whose layer has no fluid
cell. For the pressure drop across a bed, put `lower` in the first layer above the distributor
and `upper` above the bed: the drop then leaves out the bed's weight below the first layer's
centre (half a cell).
)";

template <class T>
void reference_section(std::ostringstream& s, const Section<T>& section, const std::string& head) {
  reference_table(s, head + " — " + section.title, section.infos());
}
}  // namespace

std::string key_reference_markdown() {
  std::ostringstream s;
  s << "# Deck key reference\n\n"
       "Generated by `bagnold keys` from the declarations in `src/deck/sections.cpp` and the\n"
       "models' coefficient declarations; a test fails when this file and the code disagree.\n"
       "Units are SI. Any key can be overridden with `--set section.key=value`\n"
       "(array elements: `--set boundary[1].pressure=1e5`).\n\n"
       "## `extends` — a base deck\n\n"
       "A top-level `extends = \"base.toml\"` (a string; a path relative to the deck's folder, or\n"
       "absolute) makes the deck the base deck with this file's keys laid over it: a table's keys\n"
       "replace the base's one by one, an array of tables (`[[boundary]]`, `[[initial]]`) replaces\n"
       "the base's whole. A base deck may itself extend another: a chain of at most 8 base\n"
       "decks (a longer chain, or a cycle, is refused).\n";
  reference_section(s, run_section(), "`[run]`");
  reference_section(s, physics_section(), "`[physics]`");
  reference_section(s, grid_section(), "`[grid]`");
  reference_section(s, axis_section(), "`[grid.x]`, `[grid.y]`, `[grid.z]`");
  reference_section(s, geometry_section(), "`[geometry]`");
  reference_section(s, block_section(), "`[[geometry.block]]`");
  s << "\nKeys per shape: box: min, max; half_space: point, normal; cylinder: base, axis, length,"
       " radius; cone: base, axis, length, radius, top_radius; quadric: matrix, constant, along,"
       " range (and optionally centre, linear).\n\n"
       "A quadric block is one piece of a curved wall: f(x) = (x−c)ᵀA(x−c) + bᵀ(x−c) + f0, inside"
       " where f < 0, acting only where range[0] ≤ x_along ≤ range[1]. A wall of several pieces"
       " (a hopper's hyperbola between two circles, cases/hourglass/mfix-hourglass.toml) is one"
       " block per piece, each `blocks = \"outside\"` over its own range.\n";
  reference_section(s, boundary_section(), "`[[boundary]]`");
  reference_section(s, gas_section(), "`[gas]`");
  auto solids = solids_switch_section().infos();
  for (const auto& k : solids_section().infos()) solids.push_back(k);
  reference_table(s, "`[solids]` — Granular phase", solids);
  reference_section(s, solids_stress_section(), "`[models.solids_stress]`");
  for (const auto& entry : models::stress_registry().entries())
    reference_table(s, "`[models.solids_stress." + entry.name + "]` — " + entry.summary,
                    coefficient_infos(entry.coefficients));
  reference_section(s, drag_section(), "`[models.drag]`");
  for (const auto& entry : models::drag_registry().entries())
    reference_table(s, "`[models.drag." + entry.name + "]` — " + entry.summary,
                    coefficient_infos(entry.coefficients));
  reference_section(s, initial_section(), "`[[initial]]`");
  s << region_selection_markdown;
  reference_section(s, pressure_probe_section(), "`[[pressure_probe]]`");
  s << pressure_probe_markdown;
  reference_section(s, numerics_section(), "`[numerics]`");
  reference_section(s, output_section(), "`[output]`");
  return s.str();
}

}  // namespace bagnold::deck
