#pragma once
// One named constant per regularisation of docs/formulation.md section 9 (RG1-RG7): what keeps
// Newton's matrix regular and the energy smooth where the exact model is singular or kinked.
// Each is small against the physics it touches; the page quotes these values.

namespace chute::kernels {

// RG5: Jacobian-only spring kCableSlackTangent E A0 / L between the ends of a slack tension-only
// cable or sliding-element part, so massless nodes between slack parts leave the matrix regular.
inline constexpr double kCableSlackTangent = 1e-8;

// RG6: Jacobian-only membrane tension kMembraneSlackTangent E t0 in every direction of a slack or
// wrinkled membrane element, so flat or slack fabric leaves the matrix regular.
inline constexpr double kMembraneSlackTangent = 1e-6;

}  // namespace chute::kernels
