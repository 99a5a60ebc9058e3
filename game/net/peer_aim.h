// The aim a player is editing in its turn, shown on the other side as it moves (Aiming
// messages): only drawn, never a command, never recorded. Both ends are here, as plain
// logic on wall seconds that the window hands in (the match never sees them):
//   AimSharing  the sender: an aim that changed, at most kAimSendHz times a second, and
//               the same aim again every kAimRefreshSeconds while the player holds it;
//   PeerAim     the receiver: the last aim heard, while fresh (kAimStaleSeconds: the
//               player let go, or the link stalled) and while the turn is the sender's.
#pragma once

#include <optional>

namespace game::net {

inline constexpr double kAimSendHz = 20.0;
inline constexpr double kAimRefreshSeconds = 0.4;
inline constexpr double kAimStaleSeconds = 1.0;

struct AimSeen {
    double angleDeg = 0.0, speedMps = 0.0;
    bool operator==(const AimSeen&) const = default;
};

class AimSharing {
  public:
    /// The aim being edited now (none: not editing). True when it is to be sent now.
    bool due(std::optional<AimSeen> editing, double nowSeconds);

  private:
    std::optional<AimSeen> sent_;
    double sentAt_ = 0.0;
};

class PeerAim {
  public:
    /// An Aiming message from the player of `cannon`.
    void heard(AimSeen aim, int cannon, double nowSeconds);
    /// What to draw now for the cannon whose turn it is, if anything.
    std::optional<AimSeen> shown(int turnCannon, double nowSeconds) const;

  private:
    std::optional<AimSeen> aim_;
    int cannon_ = -1;
    double heardAt_ = 0.0;
};

} // namespace game::net
