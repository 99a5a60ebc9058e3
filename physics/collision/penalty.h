// The penalty model of contact (ContactModel::Penalty): instead of an impulse at the time
// of impact, every pair that overlaps at the end of the step is pushed apart by a stiff
// damped spring over the step (penaltyImpulse, contact_impulse.h), with dynamic friction.
// The gradual response of Rabin's "Real-time Game Physics" (Introduction to Game
// Development, 4.3), kept to show what it costs: bodies sink by about g / w^2 at rest.
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/collision/substep.h"

#include <vector>

namespace phys {

/// The penalty impulses of `pairs` (the end positions' overlapping pairs, pair_cache.h).
void resolvePenaltyContacts(const Substep& sub, const std::vector<ProxyPair>& pairs);

} // namespace phys
