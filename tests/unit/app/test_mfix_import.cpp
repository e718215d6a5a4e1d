// Unit tests of reading an MFIX deck (src/app/mfix_namelist.*) and translating it into a Bagnold
// deck (src/app/mfix_import.*), on small inline decks.
#include <gtest/gtest.h>

#include "src/app/mfix_import.hpp"
#include "src/app/mfix_namelist.hpp"

#include <string>

using namespace bagnold::app::mfix;

namespace {

// The one record of `name` ("bc_x_w(3)"); fails the test when absent.
Record find(const std::vector<Record>& records, const std::string& name) {
  for (const auto& r : records)
    if (r.name() == name) return r;
  ADD_FAILURE() << name << " not parsed";
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A 10 x 20 x 10 cm box, 2 x 4 x 2 cells, with what every import needs; `extra` adds lines.
std::string box_deck(const std::string& extra) {
  return "tstop = 0.1  dt = 1e-4\n"
         "x_max = 0.1  y_max = 0.2  z_max = 0.1  imax = 2  jmax = 4  kmax = 2\n"
         "gravity_y = -9.81\n"
         "ro_g0 = 1.2  mu_g0 = 1.8e-5  d_p0(1) = 1e-3  ro_s0(1) = 2500.  ep_star = 0.42\n" +
         extra;
}

ImportResult import_text(const std::string& text, bool lenient = false) {
  return import_deck(parse_namelist(text), {.source_name = "test.dat", .lenient = lenient});
}

}  // namespace

TEST(MfixNamelist, IndicesRepeatsLogicalsStringsAndExponents) {
  const auto records = parse_namelist(
      "&INPUT_DATA\n"
      "BC_X_w(3) = 1.5d-2   ! a comment\n"
      "spx_dt = 3*0.1 2.0   # another\n"
      "IC_EP_S(2, 1) = 0.58  energy_eq = .F.  granular_energy=.TRUE.\n"
      "run_name = 'a ! b'  discretize(2) = 2*2\n"
      "/\n");
  EXPECT_EQ(find(records, "bc_x_w(3)").line, 2);
  EXPECT_DOUBLE_EQ(as_real(find(records, "bc_x_w(3)")).value(), 0.015);
  for (const char* n : {"spx_dt(1)", "spx_dt(2)", "spx_dt(3)"})
    EXPECT_DOUBLE_EQ(as_real(find(records, n)).value(), 0.1);
  EXPECT_DOUBLE_EQ(as_real(find(records, "spx_dt(4)")).value(), 2.0);
  EXPECT_DOUBLE_EQ(as_real(find(records, "ic_ep_s(2,1)")).value(), 0.58);
  EXPECT_EQ(find(records, "ic_ep_s(2,1)").line, 4);
  EXPECT_EQ(as_logical(find(records, "energy_eq")), false);
  EXPECT_EQ(as_logical(find(records, "granular_energy")), true);
  EXPECT_EQ(find(records, "run_name").value, "a ! b");
  EXPECT_TRUE(find(records, "run_name").quoted);
  EXPECT_EQ(as_integer(find(records, "discretize(3)")), 2);
  EXPECT_EQ(records.size(), 11u);  // 1 + 4 + 1 + 1 + 1 + 1 + 2
}

TEST(MfixNamelist, ASyntaxErrorNamesItsLine) {
  try {
    parse_namelist("tstop = 1.0\nrun_name = 'open\n");
    FAIL() << "an unclosed string was accepted";
  } catch (const NamelistError& e) {
    EXPECT_EQ(e.line(), 2);
  }
  EXPECT_THROW(parse_namelist("tstop 1.0\n"), NamelistError);
}

TEST(MfixImport, FrameMapsMfixYToBagnoldZ) {
  const auto p = to_bagnold_frame({1.0, 2.0, 3.0});
  EXPECT_EQ(p, (std::array<double, 3>{1.0, 3.0, 2.0}));
  const auto result = import_text(box_deck(
      "bc_type(1) = 'PO'  bc_x_w(1) = 0.0  bc_x_e(1) = 0.1  bc_y_s(1) = 0.2  bc_y_n(1) = 0.2\n"
      "bc_z_b(1) = 0.0  bc_z_t(1) = 0.05  bc_p_g(1) = 101325.\n"));
  ASSERT_TRUE(result.unsupported.empty()) << unsupported_report("test.dat", result.unsupported);
  EXPECT_TRUE(contains(result.deck, "gravity = [0.0, 0.0, -9.81]"));
  EXPECT_TRUE(contains(result.deck, "[grid.z]          # MFIX y\nmin = 0.0\nmax = 0.2\ncells = 4"));
  EXPECT_TRUE(contains(result.deck, "[grid.y]          # MFIX z\nmin = 0.0\nmax = 0.1\ncells = 2"));
  // The top of MFIX (y+) is Bagnold's z+; MFIX's z range [0, 0.05] is Bagnold's y range.
  EXPECT_TRUE(contains(result.deck, "face = \"z+\"\nmin = [0.0, 0.0, 0.2]\nmax = [0.1, 0.05, 0.4]"));
}

TEST(MfixImport, CgsIsConvertedToSi) {
  const auto result = import_text(
      "units = 'CGS'  tstop = 0.1  dt = 1e-4\n"
      "xlength = 4.0  ylength = 100.  zlength = 4.  imax = 2  jmax = 4  kmax = 2\n"
      "ro_g0 = 1.2d-3  mu_g0 = 1.8d-4  d_p0(1) = 0.1  ro_s0(1) = 2.5  ep_star = 0.42\n"
      "bc_type(1) = 'PO'  bc_x_w(1) = 0.0  bc_x_e(1) = 4.0  bc_y_s(1) = 100.  bc_y_n(1) = 100.\n"
      "bc_z_b(1) = 0.0  bc_z_t(1) = 4.0  bc_p_g(1) = 1013250.\n");
  ASSERT_TRUE(result.unsupported.empty()) << unsupported_report("test.dat", result.unsupported);
  EXPECT_TRUE(contains(result.deck, "max = 0.04\n"));
  EXPECT_TRUE(contains(result.deck, "max = 1.0\n"));
  EXPECT_TRUE(contains(result.deck, "density = 1.2 "));
  EXPECT_TRUE(contains(result.deck, "viscosity = 1.8e-05 "));
  EXPECT_TRUE(contains(result.deck, "diameter = 0.001 "));
  EXPECT_TRUE(contains(result.deck, "density = 2500.0 "));
  EXPECT_TRUE(contains(result.deck, "pressure = 101325.0 "));
  EXPECT_TRUE(contains(result.deck, "reference_pressure = 101325.0 "));
  // No gravity keyword: MFIX's default 980.665 cm/s^2 along -y.
  EXPECT_TRUE(contains(result.deck, "gravity = [0.0, 0.0, -9.80665]"));
}

TEST(MfixImport, IdealGasBecomesItsDensityAtTheReferenceState) {
  std::string deck = box_deck("mw_avg = 28.96  t_g0 = 300.0\n");
  deck.replace(deck.find("ro_g0 = 1.2"), 11, "");
  const auto result = import_text(deck);
  ASSERT_TRUE(result.unsupported.empty()) << unsupported_report("test.dat", result.unsupported);
  // 101325 Pa * 28.96 kg/kmol / (8314.46 J/(kmol K) * 300 K) = 1.17645 kg/m^3.
  EXPECT_TRUE(contains(result.deck, "density = 1.1764")) << result.deck;
  EXPECT_TRUE(contains(result.deck, "MFIX's ideal gas"));
}

TEST(MfixImport, EachBoundaryType) {
  const auto result = import_text(box_deck(
      "bc_type(1) = 'NSW'  bc_x_w(1) = 0.0  bc_x_e(1) = 0.0  bc_y_s(1) = 0.0  bc_y_n(1) = 0.2  bc_z_b(1) = 0.0  bc_z_t(1) = 0.1\n"
      "bc_type(2) = 'FSW'  bc_x_w(2) = 0.1  bc_x_e(2) = 0.1  bc_y_s(2) = 0.0  bc_y_n(2) = 0.2  bc_z_b(2) = 0.0  bc_z_t(2) = 0.1\n"
      "bc_type(3) = 'PSW'  bc_x_w(3) = 0.0  bc_x_e(3) = 0.1  bc_y_s(3) = 0.0  bc_y_n(3) = 0.2  bc_z_b(3) = 0.0  bc_z_t(3) = 0.0\n"
      "bc_jj_ps(3) = 1  phip = 0.5  e_w = 0.9\n"
      "bc_type(4) = 'MI'  bc_x_w(4) = 0.0  bc_x_e(4) = 0.05  bc_y_s(4) = 0.0  bc_y_n(4) = 0.0  bc_z_b(4) = 0.0  bc_z_t(4) = 0.1\n"
      "bc_ep_g(4) = 0.6  bc_v_g(4) = 1.5  bc_v_s(4,1) = 0.5  bc_w_s(4,1) = 0.1\n"
      "bc_type(5) = 'PI'  bc_x_w(5) = 0.05  bc_x_e(5) = 0.1  bc_y_s(5) = 0.0  bc_y_n(5) = 0.0  bc_z_b(5) = 0.0  bc_z_t(5) = 0.1  bc_p_g(5) = 101400.\n"
      "bc_type(6) = 'PO'  bc_x_w(6) = 0.0  bc_x_e(6) = 0.1  bc_y_s(6) = 0.2  bc_y_n(6) = 0.2  bc_z_b(6) = 0.0  bc_z_t(6) = 0.1  bc_p_g(6) = 101325.\n"
      "bc_type(7) = 'NSW'  bc_x_w(7) = 0.0  bc_x_e(7) = 0.1  bc_y_s(7) = 0.0  bc_y_n(7) = 0.2  bc_z_b(7) = 0.1  bc_z_t(7) = 0.1  bc_uw_g(7) = 0.3\n"));
  ASSERT_TRUE(result.unsupported.empty()) << unsupported_report("test.dat", result.unsupported);
  const std::string& d = result.deck;
  EXPECT_TRUE(contains(d, "name = \"bc1_nsw\"\ntype = \"no_slip_wall\"\nface = \"x-\""));
  EXPECT_TRUE(contains(d, "name = \"bc2_fsw\"\ntype = \"free_slip_wall\"\nface = \"x+\""));
  EXPECT_TRUE(contains(d, "name = \"bc3_psw\"\ntype = \"no_slip_wall\"\nface = \"y-\""));
  EXPECT_TRUE(contains(d, "solids_wall = \"johnson-jackson\""));
  EXPECT_TRUE(contains(d, "specularity = 0.5"));
  EXPECT_TRUE(contains(d, "wall_restitution = 0.9"));
  EXPECT_TRUE(contains(d, "type = \"mass_inflow\"\nface = \"z-\""));
  EXPECT_TRUE(contains(d, "gas_velocity = [0.0, 0.0, 1.5]"));
  EXPECT_TRUE(contains(d, "solids_velocity = [0.0, 0.1, 0.5]"));
  EXPECT_TRUE(contains(d, "solids_fraction = 0.4\n"));
  EXPECT_TRUE(contains(d, "type = \"pressure_inflow\"\nface = \"z-\""));
  EXPECT_TRUE(contains(d, "pressure = 101400.0"));
  EXPECT_TRUE(contains(d, "type = \"pressure_outflow\"\nface = \"z+\""));
  EXPECT_TRUE(contains(d, "pressure = 101325.0   # [Pa] MFIX bc_p_g\nsolids_pressure = \"zero-gradient\""));
  EXPECT_TRUE(contains(d, "type = \"moving_wall\"\nface = \"y+\""));
  EXPECT_TRUE(contains(d, "wall_velocity = [0.3, 0.0, 0.0]"));
}

TEST(MfixImport, EveryUnsupportedKeywordIsListedWithItsLine) {
  const auto result = import_text(box_deck(
      "energy_eq = .T.\n"                                             // line 5
      "kt_type = 'GD_99'   friction_model = 'SRIVASTAVA'\n"           // line 6
      "bc_type(1) = 'MO'  bc_x_w(1) = 0.0  bc_x_e(1) = 0.1  bc_y_s(1) = 0.0  bc_y_n(1) = 0.0\n"  // 7
      "bc_z_b(1) = 0.0  bc_z_t(1) = 0.1\n"
      "nscalar = 2\n"                                                 // line 9
      "discretize(1) = 2  discretize(2) = 0\n"                       // line 10
      "spx_dt(1) = 0.1\n"));                                          // noted, not refused
  std::vector<std::pair<int, std::string>> listed;
  for (const auto& u : result.unsupported) listed.emplace_back(u.line, u.keyword);
  const std::vector<std::pair<int, std::string>> expected = {
      {5, "energy_eq"}, {6, "kt_type"}, {6, "friction_model"}, {7, "bc_type(1)"},
      {9, "nscalar"}, {10, "discretize(2)"}};
  EXPECT_EQ(listed, expected);
  const std::string report = unsupported_report("deck.dat", result.unsupported);
  EXPECT_TRUE(contains(report, "deck.dat:7: bc_type(1): Bagnold has no mass outflow")) << report;
  EXPECT_TRUE(contains(report, "deck.dat:9: nscalar: no Bagnold equivalent"));
  EXPECT_TRUE(contains(result.deck, "spx_dt(1) = 0.1 (line 11): MFIX output"));
}

TEST(MfixImport, ToleranceIsBagnoldsOwnAndTolResidIsNoted) {
  // MFIX's tol_resid bounds a differently normalized sum: taken as Bagnold's tolerance, 1e-3
  // drained the imported 5 mm bin at 87 g/s against 230 converged (docs/import-mfix.md).
  const auto result = import_text(box_deck("tol_resid = 1e-3\n"));
  EXPECT_TRUE(result.unsupported.empty());
  EXPECT_TRUE(contains(result.deck, "tolerance = 0.0001   # Bagnold's default, not MFIX tol_resid"))
      << result.deck;
  EXPECT_FALSE(contains(result.deck, "tolerance = 0.001"));
  EXPECT_TRUE(contains(result.deck, "tol_resid = 1e-3 (line 5): MFIX's convergence sum"));
  const auto absent = import_text(box_deck(""));
  EXPECT_TRUE(contains(absent.deck, "tolerance = 0.0001   # Bagnold's default"));
  const auto malformed = import_text(box_deck("tol_resid = abc\n"));
  ASSERT_EQ(malformed.unsupported.size(), 1u);
  EXPECT_EQ(malformed.unsupported[0].keyword, "tol_resid");
}

TEST(MfixImport, OpeningsTakeMfixsTreatmentOfTheWallsBesideThem) {
  // MFIX's SET_FLAGS: a no-slip wall cell beside a flow boundary is free-slip in γ̇; MFIX's zero
  // viscosity in flow-boundary cells: an opening's velocity faces feel no wall shear (without
  // it the imported 10 mm bin jams; cases/bin/mfix/README.md); SET_OUTFLOW: an outflow cell
  // holds its fluid neighbour's velocity.
  const auto result = import_text(box_deck(""));
  EXPECT_TRUE(contains(result.deck, "wall_shear_beside_openings = false   # as MFIX's SET_FLAGS"))
      << result.deck;
  EXPECT_TRUE(contains(result.deck, "shear_on_opening_faces = false   # as MFIX's zero viscosity"))
      << result.deck;
  EXPECT_TRUE(contains(result.deck, "copy_velocity_into_openings = true   # as MFIX's SET_OUTFLOW"))
      << result.deck;
  EXPECT_TRUE(contains(result.deck, "copy_fluxes_into_openings = true   # as MFIX's SET_OUTFLOW_FLUXES"))
      << result.deck;
  // MFIX's harmonic face and edge means of the viscosity (AVG_H).
  EXPECT_TRUE(contains(result.deck, "viscosity_average = \"harmonic\"   # as MFIX's AVG_H")) << result.deck;
  // That the keys exist and load: cli_import_mfix_bin_* run `bagnold check` on the imports.
}

TEST(MfixImport, DetectStallIsCarriedOverWithMfixsDefaultOn) {
  EXPECT_TRUE(contains(import_text(box_deck("")).deck,
                       "detect_stall = true   # MFIX detect_stall (MFIX's default .T.)"));
  EXPECT_TRUE(contains(import_text(box_deck("detect_stall = .F.\n")).deck,
                       "detect_stall = false   # MFIX detect_stall\n"));
  const auto malformed = import_text(box_deck("detect_stall = 3\n"), true);
  ASSERT_EQ(malformed.unsupported.size(), 1u);
  EXPECT_EQ(malformed.unsupported[0].keyword, "detect_stall");
  EXPECT_TRUE(contains(malformed.deck, "detect_stall = true   # MFIX detect_stall (MFIX's default .T.)"));
}

TEST(MfixImport, ThreeDimensionalDecksTakeGamgForThePressure) {
  // A numerics choice measured on MFIX's 3-D bin decks (docs/benchmarks.md); 2-D decks keep the
  // default hypre.
  const std::string gamg = "pressure_preconditioner = \"gamg\"";
  EXPECT_TRUE(contains(import_text(box_deck("")).deck, gamg));
  std::string flat = box_deck("no_k = .T.\n");
  flat.replace(flat.find("kmax = 2"), 8, "");
  EXPECT_FALSE(contains(import_text(flat).deck, gamg));
}

TEST(MfixImport, LenientWritesTheUnsupportedAsComments) {
  const auto result = import_text(box_deck("nscalar = 2\n"), true);
  ASSERT_EQ(result.unsupported.size(), 1u);
  EXPECT_TRUE(contains(result.deck, "# Not expressible in Bagnold, left out (imported with --lenient):\n"
                                    "#   line 5: nscalar: no Bagnold equivalent\n"))
      << result.deck;
}

TEST(MfixImport, TwoDimensionalDeckHasOneCellAcrossBetweenFreeSlipWalls) {
  std::string deck = box_deck("no_k = .T.\n");
  deck.replace(deck.find("kmax = 2"), 8, "");
  const auto result = import_text(deck);
  ASSERT_TRUE(result.unsupported.empty()) << unsupported_report("test.dat", result.unsupported);
  EXPECT_TRUE(contains(result.deck, "[grid.y]          # MFIX z\nmin = 0.0\nmax = 0.1\ncells = 1"));
  EXPECT_TRUE(contains(result.deck, "type = \"free_slip_wall\"\nface = \"y-\""));
  EXPECT_TRUE(contains(result.deck, "type = \"free_slip_wall\"\nface = \"y+\""));
}
