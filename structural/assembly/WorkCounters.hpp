#pragma once
// Work a run did, counted per kind of term ("pay only for what the scene uses"): kernel
// evaluations (one per element per residual evaluation, with or without its Jacobian), sliding
// searches and output. Integer increments beside kernels that cost far more; summary.json
// reports them under "work".
namespace chute {

struct WorkCounters {
  long lineElastic = 0;   // two-node line kernel (cables, inactive sliding elements)
  long sliding = 0;       // three-node sliding kernel (active sliding elements)
  long lineMass = 0;      // inertia / weight of line elements with density
  long whirlDamping = 0;  // RG8: active sliding elements with a line node near the slider
  long pointMass = 0;     // inertia / weight of point masses
  long membrane = 0;      // membrane kernel (force, tangent, mass, weight of one element)
  long pressure = 0;      // follower-pressure kernel (one element)
  long drag = 0;          // line-drag kernel (one straight segment)
  long faceDrag = 0;      // face-drag kernel (one membrane face)
  long sliderSearch = 0;  // active-element searches, one per slider per search pass
  long contact = 0;       // contact pairs whose distance was computed (narrow phase)
  long contactLists = 0;  // contact candidate lists built (broad phase)
  long energy = 0;        // whole-system energy evaluations (probes, summary drift)
  long sceneFrames = 0;   // output frames built (geometry, fields, reactions)
  long vtuSeries = 0;     // VTU series opened (VTK's writer exists only inside one)
  long vtuFrames = 0;     // VTU files written

  WorkCounters& operator+=(const WorkCounters& o) {
    lineElastic += o.lineElastic, sliding += o.sliding, lineMass += o.lineMass;
    pointMass += o.pointMass, membrane += o.membrane, pressure += o.pressure, drag += o.drag;
    faceDrag += o.faceDrag, whirlDamping += o.whirlDamping;
    contact += o.contact, contactLists += o.contactLists;
    sliderSearch += o.sliderSearch, energy += o.energy, sceneFrames += o.sceneFrames;
    vtuSeries += o.vtuSeries, vtuFrames += o.vtuFrames;
    return *this;
  }
};

}  // namespace chute
