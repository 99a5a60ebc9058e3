#include "game/match.h"

namespace game {

bool Match::perturbShellForTest(phys::Vec2 dv) {
    if (shell_ == phys::kNoParticle || !world_.particles.alive(shell_)) return false;
    world_.particles.setVelocity(shell_, world_.particles.velocity(shell_) + dv);
    return true;
}

} // namespace game
