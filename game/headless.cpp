#include "game/headless.h"

#include <algorithm>
#include <chrono>

namespace game {

HeadlessSummary runHeadless(const Level& level, const HeadlessOptions& o) {
    using Clock = std::chrono::steady_clock;
    Session session(level, o.session);
    const std::uint64_t lastCommand = o.commands.empty() ? 0 : o.commands.back().tick;
    const std::uint64_t limit = std::min(kMaxRunTicks, o.ticks.value_or(lastCommand + 60 * 120));
    HeadlessSummary s;
    std::size_t next = 0;
    double sim = 0.0, render = 0.0;
    while (session.match().tick() < limit) {
        if (!o.ticks && session.match().over() && next >= o.commands.size()) break;
        auto t0 = Clock::now();
        while (next < o.commands.size() && o.commands[next].tick <= session.match().tick())
            session.submit(o.commands[next++]);
        session.step();
        sim += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        for (FrameSink* listener : o.listeners) listener->frame(session.match());
        if (o.sink && session.match().tick() % std::max<std::uint64_t>(1, o.every) == 0) {
            t0 = Clock::now();
            o.sink->frame(session.match());
            render += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        }
    }
    const Match& m = session.match();
    s.ticks = m.tick();
    s.finalHash = m.hash();
    s.score = m.score();
    s.shots = m.shotsFired();
    s.over = m.over();
    s.winner = m.winner();
    s.events = m.events();
    s.simMs = sim;
    s.renderMs = render;
    s.recording = session.finishedRecording();
    if (!o.session.recordFile.empty()) session.save(o.session.recordFile);
    return s;
}

} // namespace game
