#pragma once
/// @file
/// The coefficients of the Magic Formula steady-state tyre model (MF 5.2, 6.1, 6.2), one named
/// field per `.tir` key, and the table that ties each field to its key, section, unit and the
/// value used when a file leaves it out.
///
/// How to use: read a file with LoadMagicFormula (magic_formula.h) or ReadTirFile (tir_file.h);
/// evaluate with CalcMagicFormula. To fit coefficients, cast to a Jet with `params.Cast<Jet>()`.
///
/// Units: every field is SI (m, N, Pa, rad, s) whatever the file's [UNITS] section said; the
/// reader converts. The Magic Formula coefficients themselves (PCX1 ... SSZ4) are dimensionless
/// by definition, with angles in rad, and are never converted.
///
/// Defaults: a key absent from a file takes the value mfeval 4.3.1's readTIR gives it (most are
/// 0, scale factors are 1, a few come from a generic passenger-car tyre, e.g. PKY4 = 2, which is
/// what turns an MF 5.2 file without PKY4 into the MF 5.2 cornering stiffness). They live only in
/// MagicFormulaParamTable(); a default-constructed MagicFormulaParams is all zeros.

#include <span>
#include <string_view>
#include <tuple>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"

namespace hotlap::tyre {

/// Calls X(NAME) for every coefficient of MagicFormulaParams, in file order (cheap to compile,
/// unlike a 200-element std::tie).
// One row of keys a line, as the table lists them (kept out of clang-format).
// clang-format off
#define HOTLAP_MAGIC_FORMULA_FIELDS(X) \
  X(LONGVL) X(VXLOW) X(UNLOADED_RADIUS) X(WIDTH) X(ASPECT_RATIO) X(RIM_RADIUS) X(RIM_WIDTH) \
  X(INFLPRES) X(NOMPRES) X(FNOMIN) X(VERTICAL_STIFFNESS) X(BREFF) X(DREFF) X(FREFF) X(Q_RE0) \
  X(Q_V1) X(Q_V2) X(Q_FZ2) X(Q_FCX) X(Q_FCY) X(PFZ1) X(PRESMIN) X(PRESMAX) X(FZMIN) X(FZMAX) \
  X(KPUMIN) X(KPUMAX) X(ALPMIN) X(ALPMAX) X(CAMMIN) X(CAMMAX) X(LFZO) X(LCX) X(LMUX) X(LEX) \
  X(LKX) X(LHX) X(LVX) X(LCY) X(LMUY) X(LEY) X(LKY) X(LHY) X(LVY) X(LTR) X(LRES) X(LXAL) X(LYKA) \
  X(LVYKA) X(LS) X(LKYC) X(LKZC) X(LVMX) X(LMX) X(LMY) X(LMP) X(PCX1) X(PDX1) X(PDX2) X(PDX3) \
  X(PEX1) X(PEX2) X(PEX3) X(PEX4) X(PKX1) X(PKX2) X(PKX3) X(PHX1) X(PHX2) X(PVX1) X(PVX2) X(PPX1) \
  X(PPX2) X(PPX3) X(PPX4) X(RBX1) X(RBX2) X(RBX3) X(RCX1) X(REX1) X(REX2) X(RHX1) X(QSX1) X(QSX2) \
  X(QSX3) X(QSX4) X(QSX5) X(QSX6) X(QSX7) X(QSX8) X(QSX9) X(QSX10) X(QSX11) X(QSX12) X(QSX13) \
  X(QSX14) X(PPMX1) X(PCY1) X(PDY1) X(PDY2) X(PDY3) X(PEY1) X(PEY2) X(PEY3) X(PEY4) X(PEY5) \
  X(PKY1) X(PKY2) X(PKY3) X(PKY4) X(PKY5) X(PKY6) X(PKY7) X(PHY1) X(PHY2) X(PHY3) X(PVY1) X(PVY2) \
  X(PVY3) X(PVY4) X(PPY1) X(PPY2) X(PPY3) X(PPY4) X(PPY5) X(RBY1) X(RBY2) X(RBY3) X(RBY4) X(RCY1) \
  X(REY1) X(REY2) X(RHY1) X(RHY2) X(RVY1) X(RVY2) X(RVY3) X(RVY4) X(RVY5) X(RVY6) X(QSY1) X(QSY2) \
  X(QSY3) X(QSY4) X(QSY5) X(QSY6) X(QSY7) X(QSY8) X(QBZ1) X(QBZ2) X(QBZ3) X(QBZ4) X(QBZ5) X(QBZ9) \
  X(QBZ10) X(QCZ1) X(QDZ1) X(QDZ2) X(QDZ3) X(QDZ4) X(QDZ6) X(QDZ7) X(QDZ8) X(QDZ9) X(QDZ10) \
  X(QDZ11) X(QEZ1) X(QEZ2) X(QEZ3) X(QEZ4) X(QEZ5) X(QHZ1) X(QHZ2) X(QHZ3) X(QHZ4) X(PPZ1) \
  X(PPZ2) X(SSZ1) X(SSZ2) X(SSZ3) X(SSZ4)
// clang-format on

/// Which set of Magic Formula equations a file was fitted for (FITTYP, see tir_file.h).
enum class MagicFormulaVersion {
  kMf52,  ///< MF 5.2 / PAC2002 (FITTYP 5, 6, 21)
  kMf61,  ///< MF 6.1 (FITTYP 61)
  kMf62,  ///< MF 6.2 (FITTYP 62); its steady-state forces and moments are those of MF 6.1
};

/// "MF 5.2", "MF 6.1", "MF 6.2".
std::string_view MagicFormulaVersionName(MagicFormulaVersion version);

/// Magic Formula coefficients, named as in the `.tir` file, SI units. The field comments give the
/// meaning as TNO's property files do; the equations are in magic_formula.cc.
template <Scalar T>
struct MagicFormulaParams {
  MagicFormulaVersion version = MagicFormulaVersion::kMf61;  ///< selects the 5.2 variants

  // [MODEL]
  T LONGVL{};  ///< nominal speed, m/s
  T VXLOW{};   ///< lower boundary of slip calculation, m/s
  // [DIMENSION]
  T UNLOADED_RADIUS{};  ///< free tyre radius, m
  T WIDTH{};            ///< nominal section width of the tyre, m
  T ASPECT_RATIO{};     ///< nominal aspect ratio, 1
  T RIM_RADIUS{};       ///< nominal rim radius, m
  T RIM_WIDTH{};        ///< rim width, m
  // [OPERATING_CONDITIONS]
  T INFLPRES{};  ///< tyre inflation pressure, Pa
  T NOMPRES{};   ///< nominal tyre inflation pressure, Pa
  // [VERTICAL]
  T FNOMIN{};              ///< nominal wheel load, N
  T VERTICAL_STIFFNESS{};  ///< tyre vertical stiffness, N/m
  T BREFF{};               ///< low load stiffness effective rolling radius, 1
  T DREFF{};               ///< peak value of effective rolling radius, 1
  T FREFF{};               ///< high load stiffness effective rolling radius, 1
  T Q_RE0{};               ///< ratio of free tyre radius with nominal tyre radius, 1
  T Q_V1{};                ///< tyre radius increase with speed, 1
  T Q_V2{};                ///< vertical stiffness increase with speed, 1
  T Q_FZ2{};               ///< quadratic term in load vs. deflection, 1
  T Q_FCX{};               ///< longitudinal force influence on vertical stiffness, 1
  T Q_FCY{};               ///< lateral force influence on vertical stiffness, 1
  T PFZ1{};                ///< pressure effect on vertical stiffness, 1
  // [INFLATION_PRESSURE_RANGE]
  T PRESMIN{};  ///< minimum valid tyre inflation pressure, Pa
  T PRESMAX{};  ///< maximum valid tyre inflation pressure, Pa
  // [VERTICAL_FORCE_RANGE]
  T FZMIN{};  ///< minimum allowed wheel load, N
  T FZMAX{};  ///< maximum allowed wheel load, N
  // [LONG_SLIP_RANGE]
  T KPUMIN{};  ///< minimum valid wheel slip, 1
  T KPUMAX{};  ///< maximum valid wheel slip, 1
  // [SLIP_ANGLE_RANGE]
  T ALPMIN{};  ///< minimum valid slip angle, rad
  T ALPMAX{};  ///< maximum valid slip angle, rad
  // [INCLINATION_ANGLE_RANGE]
  T CAMMIN{};  ///< minimum valid camber angle, rad
  T CAMMAX{};  ///< maximum valid camber angle, rad
  // [SCALING_COEFFICIENTS]
  T LFZO{};   ///< scale factor of nominal (rated) load, 1
  T LCX{};    ///< scale factor of Fx shape factor, 1
  T LMUX{};   ///< scale factor of Fx peak friction coefficient, 1
  T LEX{};    ///< scale factor of Fx curvature factor, 1
  T LKX{};    ///< scale factor of Fx slip stiffness, 1
  T LHX{};    ///< scale factor of Fx horizontal shift, 1
  T LVX{};    ///< scale factor of Fx vertical shift, 1
  T LCY{};    ///< scale factor of Fy shape factor, 1
  T LMUY{};   ///< scale factor of Fy peak friction coefficient, 1
  T LEY{};    ///< scale factor of Fy curvature factor, 1
  T LKY{};    ///< scale factor of Fy cornering stiffness, 1
  T LHY{};    ///< scale factor of Fy horizontal shift, 1
  T LVY{};    ///< scale factor of Fy vertical shift, 1
  T LTR{};    ///< scale factor of peak of pneumatic trail, 1
  T LRES{};   ///< scale factor for offset of residual torque, 1
  T LXAL{};   ///< scale factor of alpha influence on Fx, 1
  T LYKA{};   ///< scale factor of kappa influence on Fy, 1
  T LVYKA{};  ///< scale factor of kappa induced Fy, 1
  T LS{};     ///< scale factor of moment arm of Fx, 1
  T LKYC{};   ///< scale factor of camber force stiffness, 1
  T LKZC{};   ///< scale factor of camber torque stiffness, 1
  T LVMX{};   ///< scale factor of Mx vertical shift, 1
  T LMX{};    ///< scale factor of overturning couple, 1
  T LMY{};    ///< scale factor of rolling resistance torque, 1
  T LMP{};    ///< scale factor of Parking Moment, 1
  // [LONGITUDINAL_COEFFICIENTS]
  T PCX1{};  ///< shape factor Cfx for longitudinal force, 1
  T PDX1{};  ///< longitudinal friction Mux at Fznom, 1
  T PDX2{};  ///< variation of friction Mux with load, 1
  T PDX3{};  ///< variation of friction Mux with camber squared, 1
  T PEX1{};  ///< longitudinal curvature Efx at Fznom, 1
  T PEX2{};  ///< variation of curvature Efx with load, 1
  T PEX3{};  ///< variation of curvature Efx with load squared, 1
  T PEX4{};  ///< factor in curvature Efx while driving, 1
  T PKX1{};  ///< longitudinal slip stiffness Kfx/Fz at Fznom, 1
  T PKX2{};  ///< variation of slip stiffness Kfx/Fz with load, 1
  T PKX3{};  ///< exponent in slip stiffness Kfx/Fz with load, 1
  T PHX1{};  ///< horizontal shift Shx at Fznom, 1
  T PHX2{};  ///< variation of shift Shx with load, 1
  T PVX1{};  ///< vertical shift Svx/Fz at Fznom, 1
  T PVX2{};  ///< variation of shift Svx/Fz with load, 1
  T PPX1{};  ///< linear influence of inflation pressure on longitudinal slip stiffness, 1
  T PPX2{};  ///< quadratic influence of inflation pressure on longitudinal slip stiffness, 1
  T PPX3{};  ///< linear influence of inflation pressure on peak longitudinal friction, 1
  T PPX4{};  ///< quadratic influence of inflation pressure on peak longitudinal friction, 1
  T RBX1{};  ///< slope factor for combined slip Fx reduction, 1
  T RBX2{};  ///< variation of slope Fx reduction with kappa, 1
  T RBX3{};  ///< influence of camber on stiffness for Fx combined, 1
  T RCX1{};  ///< shape factor for combined slip Fx reduction, 1
  T REX1{};  ///< curvature factor of combined Fx, 1
  T REX2{};  ///< curvature factor of combined Fx with load, 1
  T RHX1{};  ///< shift factor for combined slip Fx reduction, 1
  // [OVERTURNING_COEFFICIENTS]
  T QSX1{};   ///< vertical shift of overturning moment, 1
  T QSX2{};   ///< camber induced overturning couple, 1
  T QSX3{};   ///< fy induced overturning couple, 1
  T QSX4{};   ///< mixed load lateral force and camber on Mx, 1
  T QSX5{};   ///< load effect on Mx with lateral force and camber, 1
  T QSX6{};   ///< b-factor of load with Mx, 1
  T QSX7{};   ///< camber with load on Mx, 1
  T QSX8{};   ///< lateral force with load on Mx, 1
  T QSX9{};   ///< b-factor of lateral force with load on Mx, 1
  T QSX10{};  ///< vertical force with camber on Mx, 1
  T QSX11{};  ///< b-factor of vertical force with camber on Mx, 1
  T QSX12{};  ///< camber squared induced overturning moment, 1
  T QSX13{};  ///< lateral force induced overturning moment, 1
  T QSX14{};  ///< lateral force induced overturning moment with camber, 1
  T PPMX1{};  ///< influence of inflation pressure on overturning moment, 1
  // [LATERAL_COEFFICIENTS]
  T PCY1{};  ///< shape factor Cfy for lateral forces, 1
  T PDY1{};  ///< lateral friction Muy, 1
  T PDY2{};  ///< variation of friction Muy with load, 1
  T PDY3{};  ///< variation of friction Muy with squared camber, 1
  T PEY1{};  ///< lateral curvature Efy at Fznom, 1
  T PEY2{};  ///< variation of curvature Efy with load, 1
  T PEY3{};  ///< zero order camber dependency of curvature Efy, 1
  T PEY4{};  ///< variation of curvature Efy with camber, 1
  T PEY5{};  ///< variation of curvature Efy with camber squared, 1
  T PKY1{};  ///< maximum value of stiffness Kfy/Fznom, 1
  T PKY2{};  ///< load at which Kfy reaches maximum value, 1
  T PKY3{};  ///< variation of Kfy/Fznom with camber, 1
  T PKY4{};  ///< curvature of stiffness Kfy, 1
  T PKY5{};  ///< peak stiffness variation with camber squared, 1
  T PKY6{};  ///< fy camber stiffness factor, 1
  T PKY7{};  ///< vertical load dependency of camber stiffness, 1
  T PHY1{};  ///< horizontal shift Shy at Fznom, 1
  T PHY2{};  ///< variation of shift Shy with load, 1
  T PHY3{};  ///< variation of shift Shy with camber (MF 5.2 only), 1
  T PVY1{};  ///< vertical shift in Svy/Fz at Fznom, 1
  T PVY2{};  ///< variation of shift Svy/Fz with load, 1
  T PVY3{};  ///< variation of shift Svy/Fz with camber, 1
  T PVY4{};  ///< variation of shift Svy/Fz with camber and load, 1
  T PPY1{};  ///< influence of inflation pressure on cornering stiffness, 1
  T PPY2{};  ///< influence of inflation pressure on dependency of nominal tyre load on cornering
             ///< stiffness, 1
  T PPY3{};  ///< linear influence of inflation pressure on lateral peak friction, 1
  T PPY4{};  ///< quadratic influence of inflation pressure on lateral peak friction, 1
  T PPY5{};  ///< influence of inflation pressure on camber stiffness, 1
  T RBY1{};  ///< slope factor for combined Fy reduction, 1
  T RBY2{};  ///< variation of slope Fy reduction with alpha, 1
  T RBY3{};  ///< shift term for alpha in slope Fy reduction, 1
  T RBY4{};  ///< influence of camber on stiffness of Fy combined, 1
  T RCY1{};  ///< shape factor for combined Fy reduction, 1
  T REY1{};  ///< curvature factor of combined Fy, 1
  T REY2{};  ///< curvature factor of combined Fy with load, 1
  T RHY1{};  ///< shift factor for combined Fy reduction, 1
  T RHY2{};  ///< shift factor for combined Fy reduction with load, 1
  T RVY1{};  ///< kappa induced side force Svyk/Muy*Fz at Fznom, 1
  T RVY2{};  ///< variation of Svyk/Muy*Fz with load, 1
  T RVY3{};  ///< variation of Svyk/Muy*Fz with camber, 1
  T RVY4{};  ///< variation of Svyk/Muy*Fz with alpha, 1
  T RVY5{};  ///< variation of Svyk/Muy*Fz with kappa, 1
  T RVY6{};  ///< variation of Svyk/Muy*Fz with atan(kappa), 1
  // [ROLLING_COEFFICIENTS]
  T QSY1{};  ///< rolling resistance torque coefficient, 1
  T QSY2{};  ///< rolling resistance torque depending on Fx, 1
  T QSY3{};  ///< rolling resistance torque depending on speed, 1
  T QSY4{};  ///< rolling resistance torque depending on speed ^4, 1
  T QSY5{};  ///< rolling resistance torque depending on camber squared, 1
  T QSY6{};  ///< rolling resistance torque depending on load and camber squared, 1
  T QSY7{};  ///< rolling resistance torque coefficient load dependency, 1
  T QSY8{};  ///< rolling resistance torque coefficient pressure dependency, 1
  // [ALIGNING_COEFFICIENTS]
  T QBZ1{};   ///< trail slope factor for trail Bpt at Fznom, 1
  T QBZ2{};   ///< variation of slope Bpt with load, 1
  T QBZ3{};   ///< variation of slope Bpt with load squared, 1
  T QBZ4{};   ///< variation of slope Bpt with camber, 1
  T QBZ5{};   ///< variation of slope Bpt with absolute camber, 1
  T QBZ9{};   ///< slope factor Br of residual torque Mzr (with LKY, LMUY), 1
  T QBZ10{};  ///< factor for dimensionless cornering stiffness of Br of Mzr, 1
  T QCZ1{};   ///< shape factor Cpt for pneumatic trail, 1
  T QDZ1{};   ///< peak trail Dpt = Dpt*(Fz/Fznom*R0), 1
  T QDZ2{};   ///< variation of peak Dpt with load, 1
  T QDZ3{};   ///< variation of peak Dpt with camber, 1
  T QDZ4{};   ///< variation of peak Dpt with camber squared, 1
  T QDZ6{};   ///< peak residual torque Dmr = Dmr/(Fz*R0), 1
  T QDZ7{};   ///< variation of peak factor Dmr with load, 1
  T QDZ8{};   ///< variation of peak factor Dmr with camber, 1
  T QDZ9{};   ///< variation of peak factor Dmr with camber and load, 1
  T QDZ10{};  ///< variation of peak factor Dmr with camber squared, 1
  T QDZ11{};  ///< variation of Dmr with camber squared and load, 1
  T QEZ1{};   ///< trail curvature Ept at Fznom, 1
  T QEZ2{};   ///< variation of curvature Ept with load, 1
  T QEZ3{};   ///< variation of curvature Ept with load squared, 1
  T QEZ4{};   ///< variation of curvature Ept with sign of Alpha-t, 1
  T QEZ5{};   ///< variation of Ept with camber and sign Alpha-t, 1
  T QHZ1{};   ///< trail horizontal shift Sht at Fznom, 1
  T QHZ2{};   ///< variation of shift Sht with load, 1
  T QHZ3{};   ///< variation of shift Sht with camber, 1
  T QHZ4{};   ///< variation of shift Sht with camber and load, 1
  T PPZ1{};   ///< effect of inflation pressure on length of pneumatic trail, 1
  T PPZ2{};   ///< influence of inflation pressure on residual aligning torque, 1
  T SSZ1{};   ///< nominal value of s/R0: effect of Fx on Mz, 1
  T SSZ2{};   ///< variation of distance s/R0 with Fy/Fznom, 1
  T SSZ3{};   ///< variation of distance s/R0 with camber, 1
  T SSZ4{};   ///< variation of distance s/R0 with load and camber, 1

  /// The same coefficients in another scalar type (derivative parts start at zero).
  template <Scalar U>
  MagicFormulaParams<U> Cast() const {
    MagicFormulaParams<U> out;
    out.version = version;
#define HOTLAP_CAST_FIELD(name) out.name = ScalarCast<U>(name);
    HOTLAP_MAGIC_FORMULA_FIELDS(HOTLAP_CAST_FIELD)
#undef HOTLAP_CAST_FIELD
    return out;
  }
};

/// The physical quantity of a `.tir` value, which decides its unit conversion.
enum class TirQuantity {
  kNone,       ///< dimensionless (all Magic Formula coefficients)
  kLength,     ///< m
  kForce,      ///< N
  kAngle,      ///< rad
  kSpeed,      ///< m/s
  kPressure,   ///< Pa
  kStiffness,  ///< N/m
};

/// One coefficient: its `.tir` key and section, quantity, default and field.
struct MagicFormulaParamInfo {
  std::string_view name;     ///< key, upper case, e.g. "PCY1"
  std::string_view section;  ///< section it is written to, e.g. "LATERAL_COEFFICIENTS"
  TirQuantity quantity;
  double default_value;  ///< SI; the value mfeval 4.3.1 uses when the file has no such key
  double MagicFormulaParams<double>::*field;
  std::string_view description;  ///< as in TNO's example files
};

/// Every field of MagicFormulaParams, in file order.
std::span<const MagicFormulaParamInfo> MagicFormulaParamTable();

/// The coefficient named `name` (a `.tir` key, e.g. "PDY1"), or null if there is none.
const MagicFormulaParamInfo* FindMagicFormulaParam(std::string_view name);

/// All coefficients at their defaults (the result of reading a file that has none), MF 6.1.
MagicFormulaParams<double> MagicFormulaDefaults();

}  // namespace hotlap::tyre
