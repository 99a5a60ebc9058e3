#include "game/headless.h"

#include <algorithm>
#include <chrono>

namespace game {

namespace {
constexpr std::uint64_t kIdleTicks = 60 * 120; ///< a minute at the game's 120 Hz
} // namespace

HeadlessSummary runHeadless(const Level& level, const HeadlessOptions& o) {
    using Clock = std::chrono::steady_clock;
    Session session(level, o.session);
    // Without a length: until the match is over, or a minute after the last command given
    // or the last shot the computer fired (an autoplayed level of long flights is still
    // being played; a computer that only passes its turns, as in a sandbox, is not).
    std::uint64_t lastPlay = o.commands.empty() ? 0 : o.commands.back().tick;
    std::size_t seen = 0; // of the session's recorded commands
    auto limit = [&] {
        if (o.ticks) return std::min(kMaxRunTicks, *o.ticks);
        const std::vector<Command>& played = session.recording().commands;
        for (; seen < played.size(); ++seen)
            if (played[seen].kind == CommandKind::Fire)
                lastPlay = std::max(lastPlay, played[seen].tick);
        return std::min(kMaxRunTicks, lastPlay + kIdleTicks);
    };
    HeadlessSummary s;
    std::size_t next = 0;
    double sim = 0.0, render = 0.0;
    while (session.match().tick() < limit()) {
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
