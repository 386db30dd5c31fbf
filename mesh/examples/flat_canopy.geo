// A small flat circular canopy as a user would script it in gmsh: 8 gores, 2 m across with a
// 0.2 m vent, 8 suspension lines of 2 m to a confluence, skirt band along the hem. Physical
// groups name the parts; chute maps them in flat_canopy.toml.
//
//   gmsh flat_canopy.geo -2 -format msh41 -o flat_canopy.msh     (or let chute mesh it)
N = 8;          // gores and lines
R = 1.0;        // canopy radius (m)
Rv = 0.1;       // vent radius
Ll = 2.0;       // line length
h = 0.12;       // mesh size on the canopy
H = Sqrt(Ll^2 - R^2);  // canopy plane above the confluence

Point(1) = {0, 0, H, h};             // centre (arc centre only)
Point(2) = {0, 0, 0, h};             // confluence
For k In {0:N-1}
  a = 2 * Pi * k / N;
  Point(10 + k) = {R * Cos(a), R * Sin(a), H, h};    // skirt
  Point(30 + k) = {Rv * Cos(a), Rv * Sin(a), H, h};  // vent
EndFor
For k In {0:N-1}
  Line(100 + k) = {30 + k, 10 + k};                         // radial seam
  Circle(200 + k) = {10 + k, 1, 10 + (k + 1) % N};          // skirt arc
  Circle(300 + k) = {30 + k, 1, 30 + (k + 1) % N};          // vent arc
  Line(400 + k) = {10 + k, 2};                              // suspension line
  Transfinite Curve{400 + k} = 7;                           // 6 elements a line
EndFor
For k In {0:N-1}
  Curve Loop(500 + k) = {100 + k, 200 + k, -(100 + (k + 1) % N), -(300 + k)};
  Plane Surface(600 + k) = {500 + k};
EndFor

Physical Surface("canopy") = {600:600 + N - 1};
Physical Curve("skirt") = {200:200 + N - 1};
Physical Curve("seams") = {100:100 + N - 1};
Physical Curve("lines") = {400:400 + N - 1};
Physical Point("confluence") = {2};
