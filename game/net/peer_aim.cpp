#include "game/net/peer_aim.h"

namespace game::net {

bool AimSharing::due(std::optional<AimSeen> editing, double now) {
    if (!editing) {
        sent_.reset();
        return false;
    }
    // The first aim of an edit goes at once; then a change waits for its slot, and a
    // held aim for its refresh.
    const double since = now - sentAt_;
    if (sent_ && (*sent_ == *editing ? since < kAimRefreshSeconds : since < 1.0 / kAimSendHz))
        return false;
    sent_ = editing;
    sentAt_ = now;
    return true;
}

void PeerAim::heard(AimSeen aim, int cannon, double now) {
    aim_ = aim;
    cannon_ = cannon;
    heardAt_ = now;
}

std::optional<AimSeen> PeerAim::shown(int turnCannon, double now) const {
    if (!aim_ || cannon_ != turnCannon || now - heardAt_ > kAimStaleSeconds) return std::nullopt;
    return aim_;
}

} // namespace game::net
