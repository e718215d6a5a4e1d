// PETSc log stages of the outer iteration (log_stage.hpp), registered on first use.
#include "solver/petsc/log_stage.hpp"

#include <array>

#include "solver/petsc/busy_segments.hpp"

namespace bagnold::solver {

namespace {
constexpr std::size_t stage_count = 5;

// Each stage's PETSc log stage and busy segment (busy_segments.hpp), made on first use.
struct StageKeys {
  PetscLogStage log_stage;
  int busy_segment;
};
const StageKeys& keys(Stage stage) {
  static const std::array<StageKeys, stage_count> all = [] {
    std::array<StageKeys, stage_count> made{};
    const char* log_names[stage_count] = {"Closures", "Momentum", "Pressure", "VolumeFraction", "GranularEnergy"};
    const char* segment_names[stage_count] = {"closures stage", "momentum stage", "pressure stage",
                                              "fraction stage", "energy stage"};
    for (std::size_t i = 0; i < stage_count; ++i) {
      PetscLogStageRegister(log_names[i], &made[i].log_stage);
      made[i].busy_segment = new_busy_segment(segment_names[i]);
    }
    return made;
  }();
  return all[static_cast<std::size_t>(stage)];
}
}  // namespace

ScopedStage::ScopedStage(Stage stage, double work_units) : m_stage(stage), m_work_units(work_units) {
  PetscLogStagePush(keys(stage).log_stage);
}
ScopedStage::~ScopedStage() {
  PetscLogStagePop();
  end_busy_segment(keys(m_stage).busy_segment, m_work_units);
}

}  // namespace bagnold::solver
