#pragma once
/// @file
/// The element loop of the explicit solver (its cost): each element's rubber, cord, bulk
/// viscosity and hourglass forces added to the nodes, compiled twice, for the x86-64 baseline and
/// for AVX2 with fused multiply-adds; which one runs is an option (StepOptions::kernel,
/// docs/validation/fe-tyre.md "Speed"). The binary carries both and picks at run time, so it runs on every
/// x86-64 machine.

#include <array>
#include <cstdint>
#include <string_view>

#include <Eigen/Core>

#include "hotlap/fe/explicit_model.h"

namespace hotlap::fe {

/// The instruction set the element loop is compiled for.
enum class ElementKernel : std::uint8_t {
  kPortable,  ///< the x86-64 baseline (SSE2), on every machine
  kAvx2,      ///< AVX2 with fused multiply-add: faster; results differ in the last bits
};

/// Whether this machine can run `kernel` (kAvx2: the CPU has AVX2 and FMA; x86-64 GCC builds).
bool ElementKernelSupported(ElementKernel kernel);
/// kAvx2 where supported, else kPortable: the default of StepOptions::kernel.
ElementKernel BestElementKernel();
/// "portable" or "avx2".
const char* ElementKernelName(ElementKernel kernel);
/// The kernel named `name`: "portable", "avx2" (InputError where this machine cannot run it),
/// or "auto" (BestElementKernel()). Anything else throws InputError; messages start with `what`
/// (e.g. "--kernel").
ElementKernel ParseElementKernel(std::string_view name, std::string_view what);
/// Throws InputError unless this machine can run `kernel`.
void CheckElementKernelSupported(ElementKernel kernel);

namespace internal {

/// What the element loop reads and writes besides the forces: raw pointers into a model's tables
/// and a state's arrays (MakeElementLoopData), so that the loop holds them in registers.
struct ElementLoopData {
  const std::array<int, 8>* elements = nullptr;  ///< model.mesh.elements
  const int* element_material = nullptr;          ///< model.mesh.element_material
  const Hex8Reference* refs = nullptr;
  const YeohMaterial* materials = nullptr;
  const RebarMaterial* rebars = nullptr;
  const int* fibre_start = nullptr;
  const FibreLayer* fibres = nullptr;  ///< model.fibres_sorted
  const double* density = nullptr;
  const double* wave_speed = nullptr;
  const double* hg_stiffness = nullptr;
  const double* hg_viscous = nullptr;
  const Eigen::Vector3d* X = nullptr;        ///< reference positions, per node
  const Eigen::Vector3d* x = nullptr;        ///< positions, per node
  const Eigen::Vector3d* v = nullptr;        ///< velocities, per node
  std::array<double, 2>* energy = nullptr;  ///< out: strain and hourglass energy, per element
  double b1 = 0.0, b2 = 0.0;                ///< bulk viscosity coefficients
};

/// The loop's view of `model` with positions `x`, velocities `v` and energies `energy` (sized as
/// the mesh's nodes and elements).
ElementLoopData MakeElementLoopData(const ExplicitModel& model, const Eigen::Vector3d* x,
                                    const Eigen::Vector3d* v, std::array<double, 2>* energy);

/// Adds the forces of elements list[k] (or k if list is null), k in [k0, k1), in order, to
/// f_stored (rubber, cords, hourglass stiffness), f_bulk (bulk viscosity) and f_hourglass
/// (viscous hourglass), indexed by node, up to the first inverted element: returns its index,
/// or -1. Runs the `kernel` compilation (which must be supported).
long AddElementRange(ElementKernel kernel, const ElementLoopData& data, const int* list, long k0,
                     long k1, Eigen::Vector3d* f_stored, Eigen::Vector3d* f_bulk,
                     Eigen::Vector3d* f_hourglass);

}  // namespace internal
}  // namespace hotlap::fe
