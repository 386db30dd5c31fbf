#pragma once
// One named constant per regularisation of docs/formulation.md section 9 (RG1-RG9): what keeps
// Newton's matrix regular and the energy smooth where the exact model is singular or kinked.
// Each is small against the physics it touches; the page quotes these names and values.

namespace chute::kernels {

// RG1: apex radius of a sliding-element part as a fraction of the element's reference length
// (kernels/UniformStrainPolyline.hpp). It must be far below the strain times L of the stiffest
// cable (1e-6 for the paper's "very stiff" ropes): inside r a length is off by up to r/2, i.e. a
// strain error of 5e-10. The apex stiffness N / r is then eps 1e9 E A / L: 1e3 E A / L for
// eps = 1e-6, well within a direct solver's reach.
inline constexpr double kApexFraction = 1e-9;

// RG2: a slider closer than this fraction of its element's reference length to an end node it is
// approaching has arrived there: the step that brought it is accepted, the two are placed on the
// same point (a massless node moves for free, a massive one by at most this much) and the slider
// is handed over. Event location lands within it in one or two retries.
inline constexpr double kArrivalFraction = 1e-6;

// EX3: the arrival radius of explicit hand-overs, a fraction of the element's reference length
// (a slider whose approach stalls short of the node, the node pulled along by the short part).
inline constexpr double kExplicitArrivalFraction = 1e-6;

// RG3: node and slider are left this far apart after a hand-over (10 apex radii): the strains of
// the two elements change by 1e-8, and the new short part has its direction along the cable.
inline constexpr double kSeparationFraction = 10 * kApexFraction;

// RG4: a start or an end of a step within kSlackTautBand L of a tension-only cable's slack / taut
// switch is on it, not across it (the step that brought the cable there was cut to end on it).
inline constexpr double kSlackTautBand = 1e-6;

// RG5: Jacobian-only spring kCableSlackTangent E A0 / L between the ends of a slack tension-only
// cable or sliding-element part, so massless nodes between slack parts leave the matrix regular.
inline constexpr double kCableSlackTangent = 1e-8;
// RG10: a tension-only part slack by less than kSlackTautBand (on the kink) also takes its taut
// axial tangent E A0 / L D D^T in the Jacobian only (terms/LineElementAssembly.hpp).

// RG6: Jacobian-only membrane tension kMembraneSlackTangent E t0 in every direction of a slack or
// wrinkled membrane element, so flat or slack fabric leaves the matrix regular.
inline constexpr double kMembraneSlackTangent = 1e-6;

// RG7 (docs/friction.md FR4): angle regularisation of the wrap angle where the two parts are
// parallel (beta = pi) or aligned (beta = 0): beta is a cone in the slider's position there;
// within this angle it is replaced by the C1 quadratic. Error in exp(mu beta): at most
// mu * kWrapApexAngle / 2.
inline constexpr double kWrapApexAngle = 1e-6;

// RG7 (docs/friction.md FR16): arrival zone of a slider with friction at a node of its element,
// as a fraction of the element's reference length. The short part next to the node is a spring
// E A / L_i, and Newton iterates that aim at the node itself (L_i -> 0) pass it; the step is cut
// to end where the slider enters the zone (aimed at half its radius) and the slider is handed over
// from there. Far below a step's slip (v dt), which absorbs the hand-over's shift of the material
// coordinate.
inline constexpr double kFrictionArrivalFraction = 1e-6;

// RG8 (kernels/SliderWhirlDamping.hpp): a line node within kWhirlDampingFraction L of a slider
// has its motion about the slider, transverse to the part between them, critically damped; the
// damping coefficient stops growing below kWhirlFloorFraction L. The whirl it removes is a mode of
// the discrete line (a node with mass beside the slider's kink) that a continuous line does not
// have; measured on the C-9 (docs/applications/c9.md): 0.05 / 0.1 / 0.2 move the skirt radius at
// 1 s by 1.5 % / - / 0.2 %.
inline constexpr double kWhirlDampingFraction = 0.1;
inline constexpr double kWhirlFloorFraction = 1e-3;

// RG9 (F12b): a line node passing beside a slider, not through it (the part between them never
// turns round within one explicit step), is looked for within this fraction of the element's
// reference length; farther out a sharply folded line has l_after - l_before ~ 0 of either sign
// with nothing passing.
inline constexpr double kPassageCapture = 0.1;
// RG9: ... and only where the line's two parts leave the slider at more than 60 degrees to each
// other (the cosine below): a line folded back on itself (a rope over a pulley) has
// l_after - l_before ~ 0 on both sides, and its nodes pass the slider head on.
inline constexpr double kPassageFoldCosine = 0.5;

}  // namespace chute::kernels
