#include "ui/demo/demo_sound.h"

#include <algorithm>

namespace ui {

void DemoSound::hear(const DemoScene& scene, game::audio::Synthesizer& synth, double listenerY,
                     bool stopped) {
    for (; shotsHeard_ < scene.shotsFired(); ++shotsHeard_)
        synth.hearShot(scene.muzzle(), scene.def().muzzleSpeed);

    // The newest landings are the last ones kept (the scene keeps a few).
    const auto& landings = scene.landings();
    const auto fresh = static_cast<std::size_t>(
        std::min<std::uint64_t>(scene.landingsMade() - landingsHeard_, landings.size()));
    for (std::size_t k = landings.size() - fresh; k < landings.size(); ++k)
        if (!landings[k].vacuum)
            synth.hearLanding(landings[k].at, landings[k].speed, game::audio::Timbre::Earth);
    landingsHeard_ = scene.landingsMade();

    if (stopped) {
        synth.stillWhistles();
        return;
    }
    flying_.clear();
    for (const ShellTrack& s : scene.shells())
        if (!s.vacuum)
            flying_.push_back(
                {s.id,
                 {scene.world.particles.position(s.id), scene.world.particles.velocity(s.id)}});
    synth.hearShellsInFlight(flying_, listenerY);
}

} // namespace ui
