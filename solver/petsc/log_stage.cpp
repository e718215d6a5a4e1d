// PETSc log stages of the outer iteration (log_stage.hpp), registered on first use.
#include "solver/petsc/log_stage.hpp"

#include <array>

#include "solver/petsc/busy_segments.hpp"

namespace bagnold::solver {

namespace {
PetscLogStage stage_id(Stage stage) {
  static const std::array<PetscLogStage, 5> ids = [] {
    std::array<PetscLogStage, 5> registered{};
    const char* names[5] = {"Closures", "Momentum", "Pressure", "VolumeFraction", "GranularEnergy"};
    for (std::size_t i = 0; i < registered.size(); ++i) PetscLogStageRegister(names[i], &registered[i]);
    return registered;
  }();
  return ids[static_cast<std::size_t>(stage)];
}
}  // namespace

ScopedStage::ScopedStage(Stage stage, double work_units) : m_stage(stage), m_work_units(work_units) {
  PetscLogStagePush(stage_id(stage));
}
ScopedStage::~ScopedStage() {
  PetscLogStagePop();
  static const std::array<int, 5> segments = [] {
    std::array<int, 5> keys{};
    const char* names[5] = {"closures stage", "momentum stage", "pressure stage", "fraction stage",
                            "energy stage"};
    for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = new_busy_segment(names[i]);
    return keys;
  }();
  end_busy_segment(segments[static_cast<std::size_t>(m_stage)], m_work_units);
}

}  // namespace bagnold::solver
