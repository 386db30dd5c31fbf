// The CalculiX deck of the peer problem (bench/peer) is well-formed: every node and element once,
// the section, mass, boundary, load and step cards present, no number wider than ccx's
// 20-character field. Running ccx itself is bench/peer/run_peer.py's job (not a test dependency).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <string>

#include "CalculixInp.hpp"
#include "PeerProblem.hpp"

namespace {

using chute::bench::buildPeerProblem;
using chute::bench::CalculixOptions;
using chute::bench::PeerParams;

// Data lines counted under each keyword card (the card text up to its first comma, plus TYPE).
std::map<std::string, int> countCards(const std::string& deck, int& widest) {
  std::map<std::string, int> count;
  std::istringstream in(deck);
  std::string line, card;
  widest = 0;
  while (std::getline(in, line)) {
    if (line.rfind("*", 0) == 0) {
      card = line.substr(0, line.find(','));
      const auto type = line.find("TYPE=");
      if (type != std::string::npos) {
        std::string name = line.substr(type + 5);
        name.resize(std::min(name.size(), name.find(',')));
        card.push_back(':');
        card.append(name);
      }
      ++count[std::string(card).append("#cards")];
      continue;
    }
    ++count[card];
    if (card == "*HEADING") continue;  // free text
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) {
      const auto b = f.find_first_not_of(' ');
      if (b != std::string::npos) widest = std::max(widest, static_cast<int>(f.size() - b));
    }
  }
  return count;
}

TEST(CalculixInp, QuadCanopyDeckHasEveryNodeElementAndCard) {
  PeerParams p;
  p.square = 4;
  p.rings = 2;
  p.steps = 7;
  const auto problem = buildPeerProblem(p);
  std::ostringstream os;
  writeCalculixInp(os, problem, p, CalculixOptions{});
  int widest = 0;
  auto c = countCards(os.str(), widest);
  const auto& m = problem.spec.model;
  std::printf("nodes %d, quads %zu, trusses %zu, widest field %d characters\n", m.numNodes(),
              m.membranes.size(), m.cables.size(), widest);
  EXPECT_EQ(c["*NODE"], m.numNodes());
  EXPECT_EQ(c["*ELEMENT:M3D4"], static_cast<int>(m.membranes.size()));
  EXPECT_EQ(c["*ELEMENT:T3D2"], static_cast<int>(m.cables.size()));
  // Point masses at every free line node (rim and interior), none at the fixed confluence.
  int massNodes = 0;
  for (int n = 0; n < m.numNodes(); ++n) massNodes += m.pointMass[n] > 0 && n != problem.confluence;
  EXPECT_EQ(c["*ELEMENT:MASS"], massNodes);
  EXPECT_EQ(c["*MASS#cards"], c["*ELEMENT:MASS#cards"]);
  EXPECT_EQ(c["*MEMBRANE SECTION"], 1);
  EXPECT_EQ(c["*SOLID SECTION"], 1);
  EXPECT_EQ(c["*BOUNDARY"], 1);
  EXPECT_EQ(c["*STEP#cards"], 1);
  EXPECT_EQ(c["*END STEP#cards"], 1);
  EXPECT_EQ(c["*DLOAD"], 1);
  EXPECT_LE(widest, 20);
  const std::string deck = os.str();
  EXPECT_NE(deck.find("*STEP, NLGEOM"), std::string::npos);
  EXPECT_NE(deck.find("*DYNAMIC, DIRECT, ALPHA=0\n0.0001, 0.0007"), std::string::npos);
  EXPECT_NE(deck.find("CANOPY, P1, 100"), std::string::npos);
  EXPECT_NE(deck.find("*NODE PRINT, NSET=PROBES, FREQUENCY=1\nU\n"), std::string::npos);
  EXPECT_EQ(deck.find("*CONTROLS"), std::string::npos);  // ccx's defaults unless asked
}

TEST(CalculixInp, TrianglesWriteM3D3AndAlphaOutsideHhtRangeIsRefused) {
  PeerParams p;
  p.quads = false;
  p.rings = 3;
  const auto problem = buildPeerProblem(p);
  std::ostringstream os;
  writeCalculixInp(os, problem, p, CalculixOptions{});
  int widest = 0;
  auto c = countCards(os.str(), widest);
  EXPECT_EQ(c["*ELEMENT:M3D3"], static_cast<int>(problem.spec.model.membranes.size()));
  CalculixOptions bad;
  bad.alpha = -0.4;
  std::ostringstream ignored;
  EXPECT_THROW(writeCalculixInp(ignored, problem, p, bad), std::invalid_argument);
}

}  // namespace
