#include "game/replay.h"

#include "game/ai.h"
#include "game/files/data_folder.h"
#include "game/files/json_reader.h"

#include <cstdio>
#include <filesystem>

namespace game {

namespace fs = std::filesystem;

std::string hex(std::uint64_t v) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

Checkpoint checkpointOf(const Match& m) {
    return {m.tick(), m.hash(), m.world().hash(), m.rigid().hash(), m.gameHash()};
}

namespace {

std::uint64_t readHex(const Node& n) {
    const std::string s = n.string(16);
    if (s.size() != 16 || s.find_first_not_of("0123456789abcdef") != std::string::npos)
        n.fail("expected 16 lowercase hex digits, got \"" + s + "\"");
    return std::stoull(s, nullptr, 16);
}

} // namespace

std::string replayToJson(const Replay& r) {
    nlohmann::json j;
    j["format"] = "artillery-replay";
    j["version"] = kReplayVersion;
    j["level"] = {{"file", r.levelFile}, {"content_hash", r.levelHash}};
    j["difficulty"] = r.difficulty;
    j["cpu_seed"] = r.cpuSeed;
    j["checkpoint_every"] = r.checkpointEvery;
    j["ticks"] = r.ticks;
    j["commands"] = nlohmann::json::parse(commandsToJson(r.commands));
    nlohmann::json cps = nlohmann::json::array();
    for (const Checkpoint& c : r.checkpoints)
        cps.push_back({{"tick", c.tick},
                       {"hash", hex(c.hash)},
                       {"particles", hex(c.particles)},
                       {"bodies", hex(c.bodies)},
                       {"game", hex(c.game)}});
    j["checkpoints"] = cps;
    j["final_hash"] = hex(r.finalHash);
    return j.dump(1) + "\n";
}

Replay parseReplay(const std::string& file, const std::string& text) {
    const nlohmann::json doc = parseJson(file, text);
    const Node root(doc, file);
    if (!root.isObject()) root.fail("expected a replay object {\"format\": \"artillery-replay\", ...}");
    root.at("format").choice({"artillery-replay"});
    const long long version = root.at("version").integer(1, 1000);
    if (version != kReplayVersion)
        root.at("version").fail("this game reads replay version " + std::to_string(kReplayVersion) +
                                ", got version " + std::to_string(version));
    Replay r;
    const Node level = root.at("level");
    r.levelFile = level.string("file");
    if (r.levelFile.empty()) level.at("file").fail("expected the level's file name");
    const Node lh = level.at("content_hash");
    r.levelHash = hex(readHex(lh));
    level.finish();
    r.difficulty = root.has("difficulty") ? root.at("difficulty").choice({"easy", "normal", "hard"})
                                          : "normal";
    r.cpuSeed = static_cast<std::uint64_t>(root.integer("cpu_seed", 1, 0, 0x7fffffffffffffffll));
    r.checkpointEvery = static_cast<std::uint64_t>(root.integer("checkpoint_every", 120, 1, 1000000));
    // The same cap as `run`: verifying a replay never simulates more than a run may.
    r.ticks = static_cast<std::uint64_t>(
        root.at("ticks").integer(0, static_cast<long long>(kMaxRunTicks)));
    // Commands use the commands-file reader, at the right path.
    const Node commands = root.at("commands");
    r.commands = readCommands(commands);
    for (std::size_t i = 0; i < r.commands.size(); ++i)
        if (r.commands[i].tick > r.ticks)
            commands.elements(kMaxCommands)[i].fail("command at tick " + std::to_string(r.commands[i].tick) +
                                                   " is after the end of the replay (tick " +
                                                   std::to_string(r.ticks) + ")");
    std::uint64_t last = 0;
    for (const Node& n : root.at("checkpoints").elements(1000000)) {
        Checkpoint c;
        c.tick = static_cast<std::uint64_t>(n.at("tick").integer(1, static_cast<long long>(r.ticks)));
        if (c.tick <= last && last != 0) n.at("tick").fail("expected checkpoints in increasing tick order");
        last = c.tick;
        c.hash = readHex(n.at("hash"));
        c.particles = readHex(n.at("particles"));
        c.bodies = readHex(n.at("bodies"));
        c.game = readHex(n.at("game"));
        n.finish();
        r.checkpoints.push_back(c);
    }
    r.finalHash = readHex(root.at("final_hash"));
    root.finish();
    return r;
}

Replay loadReplay(const std::string& file) { return parseReplay(file, readFile(file)); }

void saveReplay(const std::string& file, const Replay& r) { writeFileAtomically(file, replayToJson(r)); }

Level levelForReplay(const std::string& replayFile, const Replay& r) {
    // A relative level path is looked up from the replay's folder and each folder above
    // it (a replay in tests/replays finds levels/ at the top), then in the game's data
    // folder (a shipped level, "levels/NAME.json", from an installed game), then from here.
    fs::path p = r.levelFile;
    if (p.is_relative()) {
        std::error_code ec;
        bool found = false;
        for (fs::path dir = fs::absolute(replayFile, ec).parent_path(); !dir.empty();
             dir = dir.parent_path()) {
            if (fs::exists(dir / p, ec)) {
                p = dir / p;
                found = true;
                break;
            }
            if (dir == dir.root_path()) break;
        }
        if (!found && fs::exists(fs::path(dataFolder()) / p, ec)) p = fs::path(dataFolder()) / p;
    }
    std::string text;
    try {
        text = readFile(p.string());
    } catch (const LoadError&) {
        throw LoadError(replayFile, "$.level.file",
                        "the level \"" + r.levelFile + "\" cannot be opened (looked in the replay's folder, the folders above it, the game's data folder and the working folder)");
    }
    if (contentHash(text) != r.levelHash)
        throw LoadError(replayFile, "$.level.content_hash",
                        "this replay was recorded on another version of \"" + r.levelFile +
                            "\" (content hash " + r.levelHash + ", the file now hashes to " +
                            contentHash(text) + ")");
    return parseLevel(p.string(), text);
}

namespace {

/// "tick 0: select 'nuke' refused: WHY": a command the match refused, for the warnings.
std::string refusal(const Command& c, const std::string& why) {
    std::string said = "tick " + std::to_string(c.tick) + ": " + commandName(c.kind);
    if (!c.text.empty()) said += " '" + c.text + "'";
    return said + " refused: " + why;
}

} // namespace

VerifyResult verifyReplay(const Level& level, const Replay& r) {
    VerifyResult out;
    Match m(level);
    std::size_t next = 0, cp = 0;
    auto compare = [&](const Checkpoint& want) {
        const Checkpoint got = checkpointOf(m);
        ++out.checkpoints;
        if (got.hash == want.hash || !out.ok) return;
        out.ok = false;
        out.firstDivergentTick = want.tick;
        std::string what;
        if (got.particles != want.particles) what += "particles";
        if (got.bodies != want.bodies) what += std::string(what.empty() ? "" : ", ") + "bodies";
        if (got.game != want.game) what += std::string(what.empty() ? "" : ", ") + "game";
        out.diverged = what.empty() ? "match" : what;
    };
    while (m.tick() < r.ticks) {
        while (next < r.commands.size() && r.commands[next].tick <= m.tick()) {
            const Command& c = r.commands[next++];
            if (const std::string why = m.apply(c); !why.empty())
                out.ignored.push_back(refusal(c, why));
        }
        m.step();
        while (cp < r.checkpoints.size() && r.checkpoints[cp].tick == m.tick()) compare(r.checkpoints[cp++]);
    }
    out.ticks = m.tick();
    out.finalHash = m.hash();
    if (out.ok && out.finalHash != r.finalHash) {
        out.ok = false;
        out.firstDivergentTick = r.ticks;
        out.diverged = "final state";
    }
    return out;
}

} // namespace game
