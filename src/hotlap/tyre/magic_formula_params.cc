#include "hotlap/tyre/magic_formula_params.h"

#include <array>

namespace hotlap::tyre {

namespace {

using P = MagicFormulaParams<double>;

// Defaults are those of mfeval 4.3.1's readTIR.m (which starts from a generic passenger-car
// tyre); descriptions are TNO's.
// One .tir key a line (kept out of clang-format).
// clang-format off
constexpr auto kTable = std::to_array<MagicFormulaParamInfo>({
    {"LONGVL", "MODEL", TirQuantity::kSpeed, 16.7, &P::LONGVL, "Nominal speed"},
    {"VXLOW", "MODEL", TirQuantity::kSpeed, 1, &P::VXLOW, "Lower boundary of slip calculation"},
    {"UNLOADED_RADIUS", "DIMENSION", TirQuantity::kLength, 0.3135, &P::UNLOADED_RADIUS, "Free tyre radius"},
    {"WIDTH", "DIMENSION", TirQuantity::kLength, 0.205, &P::WIDTH, "Nominal section width of the tyre"},
    {"ASPECT_RATIO", "DIMENSION", TirQuantity::kNone, 0.6, &P::ASPECT_RATIO, "Nominal aspect ratio"},
    {"RIM_RADIUS", "DIMENSION", TirQuantity::kLength, 0.1905, &P::RIM_RADIUS, "Nominal rim radius"},
    {"RIM_WIDTH", "DIMENSION", TirQuantity::kLength, 0.152, &P::RIM_WIDTH, "Rim width"},
    {"INFLPRES", "OPERATING_CONDITIONS", TirQuantity::kPressure, 220000, &P::INFLPRES, "Tyre inflation pressure"},
    {"NOMPRES", "OPERATING_CONDITIONS", TirQuantity::kPressure, 220000, &P::NOMPRES, "Nominal tyre inflation pressure"},
    {"FNOMIN", "VERTICAL", TirQuantity::kForce, 4000, &P::FNOMIN, "Nominal wheel load"},
    {"VERTICAL_STIFFNESS", "VERTICAL", TirQuantity::kStiffness, 200000, &P::VERTICAL_STIFFNESS, "Tyre vertical stiffness"},
    {"BREFF", "VERTICAL", TirQuantity::kNone, 8.4, &P::BREFF, "Low load stiffness effective rolling radius"},
    {"DREFF", "VERTICAL", TirQuantity::kNone, 0.27, &P::DREFF, "Peak value of effective rolling radius"},
    {"FREFF", "VERTICAL", TirQuantity::kNone, 0.07, &P::FREFF, "High load stiffness effective rolling radius"},
    {"Q_RE0", "VERTICAL", TirQuantity::kNone, 1, &P::Q_RE0, "Ratio of free tyre radius with nominal tyre radius"},
    {"Q_V1", "VERTICAL", TirQuantity::kNone, 0, &P::Q_V1, "Tyre radius increase with speed"},
    {"Q_V2", "VERTICAL", TirQuantity::kNone, 0, &P::Q_V2, "Vertical stiffness increase with speed"},
    {"Q_FZ2", "VERTICAL", TirQuantity::kNone, 1.0E-4, &P::Q_FZ2, "Quadratic term in load vs. deflection"},
    {"Q_FCX", "VERTICAL", TirQuantity::kNone, 0, &P::Q_FCX, "Longitudinal force influence on vertical stiffness"},
    {"Q_FCY", "VERTICAL", TirQuantity::kNone, 0, &P::Q_FCY, "Lateral force influence on vertical stiffness"},
    {"PFZ1", "VERTICAL", TirQuantity::kNone, 0, &P::PFZ1, "Pressure effect on vertical stiffness"},
    {"PRESMIN", "INFLATION_PRESSURE_RANGE", TirQuantity::kPressure, 10000, &P::PRESMIN, "Minimum valid tyre inflation pressure"},
    {"PRESMAX", "INFLATION_PRESSURE_RANGE", TirQuantity::kPressure, 1000000, &P::PRESMAX, "Maximum valid tyre inflation pressure"},
    {"FZMIN", "VERTICAL_FORCE_RANGE", TirQuantity::kForce, 100, &P::FZMIN, "Minimum allowed wheel load"},
    {"FZMAX", "VERTICAL_FORCE_RANGE", TirQuantity::kForce, 10000, &P::FZMAX, "Maximum allowed wheel load"},
    {"KPUMIN", "LONG_SLIP_RANGE", TirQuantity::kNone, -1.5, &P::KPUMIN, "Minimum valid wheel slip"},
    {"KPUMAX", "LONG_SLIP_RANGE", TirQuantity::kNone, 1.5, &P::KPUMAX, "Maximum valid wheel slip"},
    {"ALPMIN", "SLIP_ANGLE_RANGE", TirQuantity::kAngle, -1.5, &P::ALPMIN, "Minimum valid slip angle"},
    {"ALPMAX", "SLIP_ANGLE_RANGE", TirQuantity::kAngle, 1.5, &P::ALPMAX, "Maximum valid slip angle"},
    {"CAMMIN", "INCLINATION_ANGLE_RANGE", TirQuantity::kAngle, -0.175, &P::CAMMIN, "Minimum valid camber angle"},
    {"CAMMAX", "INCLINATION_ANGLE_RANGE", TirQuantity::kAngle, 0.175, &P::CAMMAX, "Maximum valid camber angle"},
    {"LFZO", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LFZO, "Scale factor of nominal (rated) load"},
    {"LCX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LCX, "Scale factor of Fx shape factor"},
    {"LMUX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LMUX, "Scale factor of Fx peak friction coefficient"},
    {"LEX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LEX, "Scale factor of Fx curvature factor"},
    {"LKX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LKX, "Scale factor of Fx slip stiffness"},
    {"LHX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LHX, "Scale factor of Fx horizontal shift"},
    {"LVX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LVX, "Scale factor of Fx vertical shift"},
    {"LCY", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LCY, "Scale factor of Fy shape factor"},
    {"LMUY", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LMUY, "Scale factor of Fy peak friction coefficient"},
    {"LEY", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LEY, "Scale factor of Fy curvature factor"},
    {"LKY", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LKY, "Scale factor of Fy cornering stiffness"},
    {"LHY", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LHY, "Scale factor of Fy horizontal shift"},
    {"LVY", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LVY, "Scale factor of Fy vertical shift"},
    {"LTR", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LTR, "Scale factor of peak of pneumatic trail"},
    {"LRES", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LRES, "Scale factor for offset of residual torque"},
    {"LXAL", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LXAL, "Scale factor of alpha influence on Fx"},
    {"LYKA", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LYKA, "Scale factor of kappa influence on Fy"},
    {"LVYKA", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LVYKA, "Scale factor of kappa induced Fy"},
    {"LS", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LS, "Scale factor of moment arm of Fx"},
    {"LKYC", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LKYC, "Scale factor of camber force stiffness"},
    {"LKZC", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LKZC, "Scale factor of camber torque stiffness"},
    {"LVMX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LVMX, "Scale factor of Mx vertical shift"},
    {"LMX", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LMX, "Scale factor of overturning couple"},
    {"LMY", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LMY, "Scale factor of rolling resistance torque"},
    {"LMP", "SCALING_COEFFICIENTS", TirQuantity::kNone, 1, &P::LMP, "Scale factor of Parking Moment"},
    {"PCX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 1.65, &P::PCX1, "Shape factor Cfx for longitudinal force"},
    {"PDX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 1.3, &P::PDX1, "Longitudinal friction Mux at Fznom"},
    {"PDX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, -0.15, &P::PDX2, "Variation of friction Mux with load"},
    {"PDX3", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PDX3, "Variation of friction Mux with camber squared"},
    {"PEX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEX1, "Longitudinal curvature Efx at Fznom"},
    {"PEX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEX2, "Variation of curvature Efx with load"},
    {"PEX3", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEX3, "Variation of curvature Efx with load squared"},
    {"PEX4", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEX4, "Factor in curvature Efx while driving"},
    {"PKX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 20, &P::PKX1, "Longitudinal slip stiffness Kfx/Fz at Fznom"},
    {"PKX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PKX2, "Variation of slip stiffness Kfx/Fz with load"},
    {"PKX3", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PKX3, "Exponent in slip stiffness Kfx/Fz with load"},
    {"PHX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PHX1, "Horizontal shift Shx at Fznom"},
    {"PHX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PHX2, "Variation of shift Shx with load"},
    {"PVX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PVX1, "Vertical shift Svx/Fz at Fznom"},
    {"PVX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PVX2, "Variation of shift Svx/Fz with load"},
    {"PPX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPX1, "linear influence of inflation pressure on longitudinal slip stiffness"},
    {"PPX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPX2, "quadratic influence of inflation pressure on longitudinal slip stiffness"},
    {"PPX3", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPX3, "linear influence of inflation pressure on peak longitudinal friction"},
    {"PPX4", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPX4, "quadratic influence of inflation pressure on peak longitudinal friction"},
    {"RBX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 20, &P::RBX1, "Slope factor for combined slip Fx reduction"},
    {"RBX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 15, &P::RBX2, "Variation of slope Fx reduction with kappa"},
    {"RBX3", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RBX3, "Influence of camber on stiffness for Fx combined"},
    {"RCX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 1, &P::RCX1, "Shape factor for combined slip Fx reduction"},
    {"REX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::REX1, "Curvature factor of combined Fx"},
    {"REX2", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::REX2, "Curvature factor of combined Fx with load"},
    {"RHX1", "LONGITUDINAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RHX1, "Shift factor for combined slip Fx reduction"},
    {"QSX1", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX1, "Vertical shift of overturning moment"},
    {"QSX2", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX2, "Camber induced overturning couple"},
    {"QSX3", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX3, "Fy induced overturning couple"},
    {"QSX4", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 5, &P::QSX4, "Mixed load lateral force and camber on Mx"},
    {"QSX5", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 1, &P::QSX5, "Load effect on Mx with lateral force and camber"},
    {"QSX6", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 10, &P::QSX6, "B-factor of load with Mx"},
    {"QSX7", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX7, "Camber with load on Mx"},
    {"QSX8", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX8, "Lateral force with load on Mx"},
    {"QSX9", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0.4, &P::QSX9, "B-factor of lateral force with load on Mx"},
    {"QSX10", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX10, "Vertical force with camber on Mx"},
    {"QSX11", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 5, &P::QSX11, "B-factor of vertical force with camber on Mx"},
    {"QSX12", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX12, "Camber squared induced overturning moment"},
    {"QSX13", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX13, "Lateral force induced overturning moment"},
    {"QSX14", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSX14, "Lateral force induced overturning moment with camber"},
    {"PPMX1", "OVERTURNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPMX1, "Influence of inflation pressure on overturning moment"},
    {"PCY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 1.3, &P::PCY1, "Shape factor Cfy for lateral forces"},
    {"PDY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 1.1, &P::PDY1, "Lateral friction Muy"},
    {"PDY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, -0.15, &P::PDY2, "Variation of friction Muy with load"},
    {"PDY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PDY3, "Variation of friction Muy with squared camber"},
    {"PEY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEY1, "Lateral curvature Efy at Fznom"},
    {"PEY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEY2, "Variation of curvature Efy with load"},
    {"PEY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEY3, "Zero order camber dependency of curvature Efy"},
    {"PEY4", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEY4, "Variation of curvature Efy with camber"},
    {"PEY5", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PEY5, "Variation of curvature Efy with camber squared"},
    {"PKY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, -20, &P::PKY1, "Maximum value of stiffness Kfy/Fznom"},
    {"PKY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 1, &P::PKY2, "Load at which Kfy reaches maximum value"},
    {"PKY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PKY3, "Variation of Kfy/Fznom with camber"},
    {"PKY4", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 2, &P::PKY4, "Curvature of stiffness Kfy"},
    {"PKY5", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PKY5, "Peak stiffness variation with camber squared"},
    {"PKY6", "LATERAL_COEFFICIENTS", TirQuantity::kNone, -1, &P::PKY6, "Fy camber stiffness factor"},
    {"PKY7", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PKY7, "Vertical load dependency of camber stiffness"},
    {"PHY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PHY1, "Horizontal shift Shy at Fznom"},
    {"PHY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PHY2, "Variation of shift Shy with load"},
    {"PHY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PHY3, "Variation of shift Shy with camber (MF 5.2 only)"},
    {"PVY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PVY1, "Vertical shift in Svy/Fz at Fznom"},
    {"PVY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PVY2, "Variation of shift Svy/Fz with load"},
    {"PVY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PVY3, "Variation of shift Svy/Fz with camber"},
    {"PVY4", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PVY4, "Variation of shift Svy/Fz with camber and load"},
    {"PPY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPY1, "influence of inflation pressure on cornering stiffness"},
    {"PPY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPY2, "influence of inflation pressure on dependency of nominal tyre load on cornering stiffness"},
    {"PPY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPY3, "linear influence of inflation pressure on lateral peak friction"},
    {"PPY4", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPY4, "quadratic influence of inflation pressure on lateral peak friction"},
    {"PPY5", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPY5, "Influence of inflation pressure on camber stiffness"},
    {"RBY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 10, &P::RBY1, "Slope factor for combined Fy reduction"},
    {"RBY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 10, &P::RBY2, "Variation of slope Fy reduction with alpha"},
    {"RBY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RBY3, "Shift term for alpha in slope Fy reduction"},
    {"RBY4", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RBY4, "Influence of camber on stiffness of Fy combined"},
    {"RCY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 1, &P::RCY1, "Shape factor for combined Fy reduction"},
    {"REY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::REY1, "Curvature factor of combined Fy"},
    {"REY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::REY2, "Curvature factor of combined Fy with load"},
    {"RHY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RHY1, "Shift factor for combined Fy reduction"},
    {"RHY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RHY2, "Shift factor for combined Fy reduction with load"},
    {"RVY1", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RVY1, "Kappa induced side force Svyk/Muy*Fz at Fznom"},
    {"RVY2", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RVY2, "Variation of Svyk/Muy*Fz with load"},
    {"RVY3", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 0, &P::RVY3, "Variation of Svyk/Muy*Fz with camber"},
    {"RVY4", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 20, &P::RVY4, "Variation of Svyk/Muy*Fz with alpha"},
    {"RVY5", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 2, &P::RVY5, "Variation of Svyk/Muy*Fz with kappa"},
    {"RVY6", "LATERAL_COEFFICIENTS", TirQuantity::kNone, 10, &P::RVY6, "Variation of Svyk/Muy*Fz with atan(kappa)"},
    {"QSY1", "ROLLING_COEFFICIENTS", TirQuantity::kNone, 0.01, &P::QSY1, "Rolling resistance torque coefficient"},
    {"QSY2", "ROLLING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSY2, "Rolling resistance torque depending on Fx"},
    {"QSY3", "ROLLING_COEFFICIENTS", TirQuantity::kNone, 4.0E-4, &P::QSY3, "Rolling resistance torque depending on speed"},
    {"QSY4", "ROLLING_COEFFICIENTS", TirQuantity::kNone, 4.0E-5, &P::QSY4, "Rolling resistance torque depending on speed ^4"},
    {"QSY5", "ROLLING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSY5, "Rolling resistance torque depending on camber squared"},
    {"QSY6", "ROLLING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QSY6, "Rolling resistance torque depending on load and camber squared"},
    {"QSY7", "ROLLING_COEFFICIENTS", TirQuantity::kNone, 0.85, &P::QSY7, "Rolling resistance torque coefficient load dependency"},
    {"QSY8", "ROLLING_COEFFICIENTS", TirQuantity::kNone, -0.4, &P::QSY8, "Rolling resistance torque coefficient pressure dependency"},
    {"QBZ1", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 10, &P::QBZ1, "Trail slope factor for trail Bpt at Fznom"},
    {"QBZ2", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QBZ2, "Variation of slope Bpt with load"},
    {"QBZ3", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QBZ3, "Variation of slope Bpt with load squared"},
    {"QBZ4", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QBZ4, "Variation of slope Bpt with camber"},
    {"QBZ5", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QBZ5, "Variation of slope Bpt with absolute camber"},
    {"QBZ9", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 10, &P::QBZ9, "Factor for scaling factors of slope factor Br of Mzr"},
    {"QBZ10", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QBZ10, "Factor for dimensionless cornering stiffness of Br of Mzr"},
    {"QCZ1", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 1.1, &P::QCZ1, "Shape factor Cpt for pneumatic trail"},
    {"QDZ1", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0.12, &P::QDZ1, "Peak trail Dpt = Dpt*(Fz/Fznom*R0)"},
    {"QDZ2", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ2, "Variation of peak Dpt with load"},
    {"QDZ3", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ3, "Variation of peak Dpt with camber"},
    {"QDZ4", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ4, "Variation of peak Dpt with camber squared"},
    {"QDZ6", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ6, "Peak residual torque Dmr = Dmr/(Fz*R0)"},
    {"QDZ7", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ7, "Variation of peak factor Dmr with load"},
    {"QDZ8", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, -0.05, &P::QDZ8, "Variation of peak factor Dmr with camber"},
    {"QDZ9", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ9, "Variation of peak factor Dmr with camber and load"},
    {"QDZ10", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ10, "Variation of peak factor Dmr with camber squared"},
    {"QDZ11", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QDZ11, "Variation of Dmr with camber squared and load"},
    {"QEZ1", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QEZ1, "Trail curvature Ept at Fznom"},
    {"QEZ2", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QEZ2, "Variation of curvature Ept with load"},
    {"QEZ3", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QEZ3, "Variation of curvature Ept with load squared"},
    {"QEZ4", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QEZ4, "Variation of curvature Ept with sign of Alpha-t"},
    {"QEZ5", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QEZ5, "Variation of Ept with camber and sign Alpha-t"},
    {"QHZ1", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QHZ1, "Trail horizontal shift Sht at Fznom"},
    {"QHZ2", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QHZ2, "Variation of shift Sht with load"},
    {"QHZ3", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QHZ3, "Variation of shift Sht with camber"},
    {"QHZ4", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::QHZ4, "Variation of shift Sht with camber and load"},
    {"PPZ1", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPZ1, "effect of inflation pressure on length of pneumatic trail"},
    {"PPZ2", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::PPZ2, "Influence of inflation pressure on residual aligning torque"},
    {"SSZ1", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::SSZ1, "Nominal value of s/R0: effect of Fx on Mz"},
    {"SSZ2", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::SSZ2, "Variation of distance s/R0 with Fy/Fznom"},
    {"SSZ3", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::SSZ3, "Variation of distance s/R0 with camber"},
    {"SSZ4", "ALIGNING_COEFFICIENTS", TirQuantity::kNone, 0, &P::SSZ4, "Variation of distance s/R0 with load and camber"},
});
// clang-format on

#define HOTLAP_COUNT_FIELD(name) +1
static_assert(0 HOTLAP_MAGIC_FORMULA_FIELDS(HOTLAP_COUNT_FIELD) == kTable.size(),
              "HOTLAP_MAGIC_FORMULA_FIELDS and the table must list the same fields");
#undef HOTLAP_COUNT_FIELD

}  // namespace

std::string_view MagicFormulaVersionName(MagicFormulaVersion version) {
  switch (version) {
    case MagicFormulaVersion::kMf52:
      return "MF 5.2";
    case MagicFormulaVersion::kMf61:
      return "MF 6.1";
    case MagicFormulaVersion::kMf62:
      return "MF 6.2";
  }
  return "MF ?";
}

std::span<const MagicFormulaParamInfo> MagicFormulaParamTable() { return kTable; }

const MagicFormulaParamInfo* FindMagicFormulaParam(std::string_view name) {
  for (const MagicFormulaParamInfo& info : kTable) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

MagicFormulaParams<double> MagicFormulaDefaults() {
  P p;
  for (const MagicFormulaParamInfo& info : kTable) p.*info.field = info.default_value;
  return p;
}

}  // namespace hotlap::tyre
