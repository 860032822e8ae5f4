// The Gen-7-like car's left-side tyre (a Magic Formula .tir file shipped with hotlap): lateral
// force against slip angle at three loads, the curve a tyre engineer looks at first.
//
//   ./tyre_curve [FILE.tir]

#include <cstdio>
#include <exception>
#include <filesystem>

#include "hotlap/common/data_path.h"
#include "hotlap/tyre/tyre_force_model.h"

int main(int argc, char** argv) {
  namespace tyre = hotlap::tyre;
  try {
    const std::filesystem::path file =
        argc > 1 ? std::filesystem::path(argv[1]) : hotlap::DataDir() / "cars/gen7/tyres/left.tir";
    const tyre::TyreForceModel<double> model = tyre::LoadTyreForceModel(file);
    std::printf("%s\nslip_angle_deg,fy_N_at_3000N,fy_N_at_6000N,fy_N_at_9000N\n",
                file.string().c_str());
    for (int deg = 0; deg <= 12; ++deg) {
      std::printf("%d", deg);
      for (const double fz : {3000.0, 6000.0, 9000.0}) {
        tyre::TyreOperatingPoint<double> op;
        op.fz = fz;
        op.slip_angle = deg * 3.14159265358979 / 180.0;
        op.speed = 40.0;
        op.tread_temp = 353.15;  // 80 degC
        std::printf(",%.1f", tyre::CalcTyreForces(model, op).fy);
      }
      std::printf("\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
