// A test-support program: prints the rheometer CSV of one model for lists of φ and γ̇, built from
// models/ alone, so tools/plot-closures can draw the report's figures before the full
// `bagnold rheometer` command exists. Usage:
//   rheometer_table MODEL --phi 0.1,0.2 --shear-rate 1,10 [--set KEY=VALUE ...]
// KEY is solids.diameter|density|restitution|friction|stiffness|bond_number, or one of the
// model's own coefficients (a number, or a choice such as psi_exponent=openfoam).
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "models/stress/rheometer.hpp"

namespace {
using namespace bagnold::models;

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) values.push_back(std::stod(item));
  return values;
}

bool set_material(Material& m, const std::string& key, double value) {
  if (key == "solids.diameter")
    m.diameter = value;
  else if (key == "solids.density")
    m.density = value;
  else if (key == "solids.restitution")
    m.restitution = value;
  else if (key == "solids.friction")
    m.friction = value;
  else if (key == "solids.stiffness")
    m.stiffness = value;
  else if (key == "solids.bond_number")
    m.bond_number = value;
  else
    return false;
  return true;
}
}  // namespace

int main(int argc, char** argv) try {
  if (argc < 2) {
    std::cerr << "usage: rheometer_table MODEL --phi LIST --shear-rate LIST [--set KEY=VALUE]\n";
    return 2;
  }
  const std::string model_name = argv[1];
  std::vector<double> phis, rates;
  Material material;
  Coefficients given;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--phi") {
      phis = parse_list(value);
    } else if (flag == "--shear-rate") {
      rates = parse_list(value);
    } else if (flag == "--set") {
      const auto eq = value.find('=');
      if (eq == std::string::npos) throw std::invalid_argument("--set needs KEY=VALUE");
      const std::string key = value.substr(0, eq), text = value.substr(eq + 1);
      char* end = nullptr;
      const double number = std::strtod(text.c_str(), &end);
      const bool is_number = end && *end == '\0' && !text.empty();
      if (is_number && set_material(material, key, number)) continue;
      if (is_number)
        given[key] = number;
      else
        given[key] = text;
    } else {
      throw std::invalid_argument("unknown argument '" + flag + "'");
    }
  }
  const auto model = stress_registry().create(model_name, given);
  write_rheometer_csv(std::cout, shear_rheometer(*model, material, phis, rates), true);
  return 0;
} catch (const std::exception& e) {
  std::cerr << "rheometer_table: " << e.what() << '\n';
  return 1;
}
