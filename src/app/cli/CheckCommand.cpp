#include "cli/Commands.hpp"
#include "cli/ProgressBar.hpp"
#include "cli/SolutionJson.hpp"
#include "cli/StagedDifficulty.hpp"
#include "cli/UsageError.hpp"

#include <abalike/design/ModelPlayer.hpp>
#include <abalike/design/Solver.hpp>
#include <abalike/design/StarThresholds.hpp>
#include <abalike/design/WhyNotWon.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelLimits.hpp>
#include <abalike/level/LevelText.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/PushApart.hpp>
#include <abalike/level/SafeText.hpp>
#include <abalike/save/AtomicWrite.hpp>
#include <abalike/teach/Claims.hpp>
#include <abalike/teach/TextValues.hpp>
#include <abalike/world/RestCheck.hpp>
#include <abalike/world/RestFindings.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace abalike::app
{

namespace
{

/// Box2D's documentation: stacking degrades when a body rests on one more than ten times lighter.
constexpr double kMaxStackMassRatio = 10.0;

struct CheckArgs
{
    std::vector<std::string> files;
    bool json = false;
    bool solve = false;
    bool fix = false;
    bool writeStars = false; ///< --write-stars: the recommended thresholds into the file
    bool texts = false;
    std::vector<std::string> fill; ///< texts to fill with each level's values (--fill)
    int threads = 0;
    std::size_t playerRuns = 40;
};

/// A level to check, and the campaign episode that lists it (if any).
struct CheckItem
{
    std::string file;
    std::string episode;
};

/// Everything found about one file.
struct FileReport
{
    std::string file;
    std::optional<LevelDef> level;
    std::vector<LevelIssue> issues;
    std::optional<RestReport> rest;
    std::optional<Solution> solution;
    std::optional<PlayerDifficulty> player;
    std::vector<std::string> reasons;                   ///< why it fails, one short phrase each
    std::vector<std::string> warnings;                  ///< worth a look, but the level is fine
    std::vector<std::string> fixes;                     ///< what --fix changed in the file
    std::optional<std::array<int, 3>> recommendedStars; ///< from the model player's wins (--solve)
    bool starsWritten = false;                          ///< --write-stars wrote them into the file

    bool ok() const { return reasons.empty(); }
};

/// The same file however it is spelled (levels/x.json, ./levels/x.json).
std::string canonical(const std::string& path)
{
    std::error_code ec;
    const auto resolved = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : resolved.string();
}

/// Level files as given; a campaign manifest stands for every level it lists. Each file is checked once (with its
/// episode, if a manifest lists it), however often it is named.
std::vector<CheckItem> expand(const std::vector<std::string>& files, std::vector<FileReport>& manifestFailures)
{
    std::vector<CheckItem> items;
    std::map<std::string, std::size_t> seen;
    const auto add = [&](const std::string& file, const std::string& episode)
    {
        const auto [it, inserted] = seen.emplace(canonical(file), items.size());
        if (inserted)
            items.push_back({file, episode});
        else if (!episode.empty())
            items[it->second].episode = episode;
    };
    for (const std::string& file : files)
    {
        if (!isCampaignManifest(file))
        {
            add(file, "");
            continue;
        }
        // Every problem of the manifest at once, at its own lines: entries that are missing, listed twice or
        // sandbox scenes, levels whose episode or id disagrees. The levels themselves are checked one by one below.
        std::vector<LevelIssue> manifestIssues;
        try
        {
            loadCampaignLevels(file, Catalog::builtin());
        }
        catch (const LevelLoadError& e)
        {
            for (const LevelIssue& issue : e.issues())
                if (canonical(issue.file) == canonical(file))
                    manifestIssues.push_back(issue);
        }
        if (!manifestIssues.empty())
        {
            FileReport report;
            report.file = file;
            report.reasons.push_back(std::to_string(manifestIssues.size()) + " error(s) in the campaign manifest");
            report.issues = std::move(manifestIssues);
            manifestFailures.push_back(std::move(report));
        }
        try
        {
            for (const CampaignEpisode& episode : loadCampaignEpisodes(file, true))
                for (const std::string& level : episode.levelPaths)
                    add(level, episode.id);
        }
        catch (const LevelLoadError&)
        {
            // Unreadable as JSON: loadCampaignLevels has reported why.
        }
    }
    return items;
}

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string shortest(double value)
{
    std::ostringstream out;
    out << std::setprecision(10) << std::round(value * 10000.0) / 10000.0;
    return out.str();
}

/// check --fix: makes every verified fix of the rest findings (restFindings: a new y for a body that floats or
/// overlaps, x for one past its supports' edge, angle_deg for one leaning on a corner), rewriting just those numbers
/// in the file, round after round while the level fails and a verified fix remains. Returns what it changed, one line
/// each, then what it could not fix ("not fixed: ...") with the finding that says why.
std::vector<std::string> fixRestFindings(const std::string& file, LevelDef& level)
{
    std::vector<std::string> changes;
    for (int round = 0; round < 8; ++round)
    {
        const RestReport rest = checkRest(level);
        if (rest.passed())
            return changes;
        const std::vector<RestFinding> findings = restFindings(level, Catalog::builtin(), rest);
        std::string text = readText(file);
        bool changed = false;
        // One number of one body ("/blocks/3" and "y"), in the level and in the file, with why it changed.
        const auto set =
            [&](const std::string& body, const char* key, std::optional<double> value, const std::string& why)
        {
            const bool pig = body.rfind("/pigs/", 0) == 0;
            const auto i = static_cast<std::size_t>(std::stoi(body.substr(pig ? 6 : 8)));
            const std::string_view name(key);
            double& field = name == "y"   ? (pig ? level.pigs[i].y : level.blocks[i].y)
                            : name == "x" ? (pig ? level.pigs[i].x : level.blocks[i].x)
                                          : level.blocks[i].angleDeg;
            if (!value || std::abs(*value - field) < 1e-9)
                return;
            const std::string number = shortest(*value);
            try
            {
                text = replaceNumber(text, body + "/" + key, number);
            }
            catch (const std::invalid_argument&)
            {
                return; // not written in the file (a default): left to the designer, who reads the finding
            }
            changes.push_back(body + "/" + key + ": " + shortest(field) + " -> " + number + " (" + why + ")");
            field = *value;
            changed = true;
        };
        for (const RestFinding& finding : findings)
        {
            const std::string why = finding.what.substr(0, finding.what.find(';'));
            if (finding.groupX)
            {
                // A leaning stack: the body and the ones on it, straight up.
                set(finding.pointer, "x", finding.groupX, "stacked straight");
                for (const std::string& member : finding.consequences)
                    set(member, "x", finding.groupX, "stacked straight");
                continue;
            }
            if (finding.groupDy)
                for (const std::string& member : finding.movedWith)
                {
                    // Its load moves with it, by the same height.
                    const bool pig = member.rfind("/pigs/", 0) == 0;
                    const auto m = static_cast<std::size_t>(std::stoi(member.substr(pig ? 6 : 8)));
                    set(member, "y", (pig ? level.pigs[m].y : level.blocks[m].y) + *finding.groupDy,
                        "carried by " + finding.pointer);
                }
            set(finding.pointer, "y", finding.fixY, why);
            set(finding.pointer, "x", finding.fixX, why);
            if (finding.pointer.rfind("/blocks/", 0) == 0)
                set(finding.pointer, "angle_deg", finding.fixAngleDeg, why);
        }
        if (!changed)
        {
            for (const RestFinding& finding : findings)
                changes.push_back("not fixed: " + finding.pointer + ": " + finding.message());
            return changes;
        }
        writeFileAtomically(file, text);
    }
    return changes;
}

/// check --fix, before anything else: bodies that overlap one another or reach into the ground (the loader refuses
/// the file for them) pushed apart the way a physics engine's first step would (pushOutOfGround, pushApartOverlaps:
/// the nearest free place, on the millimetre), rewriting just those numbers. The rest test then judges the result.
std::vector<std::string> fixOverlaps(const std::string& file)
{
    std::vector<std::string> changes;
    std::optional<EditableLevel> editable;
    try
    {
        editable = loadLevelForEditing(file, Catalog::builtin());
    }
    catch (const LevelLoadError&)
    {
        return changes; // not a level yet: its errors are reported as they are
    }
    if (editable->geometryIssues.empty())
        return changes;
    LevelDef level = editable->level;
    std::vector<PushedBody> moved = pushOutOfGround(level, Catalog::builtin());
    for (PushedBody& body : pushApartOverlaps(level, Catalog::builtin(), limits::kOverlapToleranceM / 2.0))
        moved.push_back(std::move(body));
    std::string text = readText(file);
    for (const PushedBody& body : moved)
    {
        const bool pig = body.pointer.rfind("/pigs/", 0) == 0;
        const auto i = static_cast<std::size_t>(std::stoi(body.pointer.substr(pig ? 6 : 8)));
        const bool up = body.dyM != 0.0;
        const double before = up ? (pig ? editable->level.pigs[i].y : editable->level.blocks[i].y)
                                 : (pig ? editable->level.pigs[i].x : editable->level.blocks[i].x);
        const double after =
            up ? (pig ? level.pigs[i].y : level.blocks[i].y) : (pig ? level.pigs[i].x : level.blocks[i].x);
        const std::string key = body.pointer + (up ? "/y" : "/x");
        try
        {
            text = replaceNumber(text, key, shortest(after));
        }
        catch (const std::invalid_argument&)
        {
            continue; // not written in the file (a default): left to the designer
        }
        std::ostringstream why;
        why << std::fixed << std::setprecision(1) << (body.other == "the ground" ? "reached " : "overlapped ")
            << (body.other == "the ground" ? "" : body.other + " by ") << body.depthM * 100.0 << " cm"
            << (body.other == "the ground" ? " below the ground" : "");
        changes.push_back(key + ": " + shortest(before) + " -> " + shortest(after) + " (" + why.str() + ")");
    }
    if (!changes.empty())
        writeFileAtomically(file, text);
    return changes;
}

FileReport checkFile(const CheckItem& item, const CheckArgs& a)
{
    FileReport report;
    report.file = item.file;
    if (a.fix)
        report.fixes = fixOverlaps(item.file);
    try
    {
        report.level = loadLevel(item.file, Catalog::builtin());
    }
    catch (const LevelLoadError& e)
    {
        report.issues = e.issues();
        std::string reason = std::to_string(e.issues().size()) + " error(s)";
        if (!e.issues().empty())
        {
            const LevelIssue& first = e.issues().front();
            reason += ", first at " + std::to_string(first.line) + ":" + std::to_string(first.column) + " " +
                      (first.pointer.empty() ? "/" : first.pointer) + ": " + first.message;
        }
        report.reasons.push_back(reason);
        return report;
    }
    const LevelDef& level = *report.level;
    if (!item.episode.empty() && level.episode != item.episode)
    {
        // The game files a level under the episode it says; one that says none would be nowhere.
        LevelIssue issue{item.file, 0, 0, level.episode.empty() ? "" : "/episode",
                         level.episode.empty()
                             ? "has no \"episode\", and the campaign lists it in episode \"" + item.episode +
                                   "\"; fix: add \"episode\": \"" + item.episode + "\""
                             : "says \"episode\": \"" + level.episode + "\" but the campaign lists it in episode \"" +
                                   item.episode + "\"; fix: set \"episode\": \"" + item.episode + "\""};
        std::vector<LevelIssue> located{issue};
        locateIssues(located, readText(item.file), item.file);
        report.reasons.push_back(located.front().message);
        report.issues.push_back(located.front());
    }

    // What the texts promise, computed for this level: a promise that does not hold is an error at its claim.
    std::vector<LevelIssue> falseClaims;
    for (std::size_t i = 0; i < level.claims.size(); ++i)
    {
        const ClaimResult claim = evaluateClaim(level.claims[i], level, Catalog::builtin());
        if (!claim.holds)
            falseClaims.push_back({item.file, 0, 0,
                                   "/claims/" + std::to_string(i) +
                                       (level.claims[i].outcome       ? "/outcome"
                                        : level.claims[i].cannotBreak ? "/cannot_break"
                                        : level.claims[i].reach       ? "/full_pull_reach"
                                                                      : "/holds"),
                                   "does not hold for this level: " + claim.message + " (so " + level.claims[i].about +
                                       " says something untrue)"});
    }
    if (!falseClaims.empty())
    {
        locateIssues(falseClaims, readText(item.file), item.file);
        report.reasons.push_back(std::to_string(falseClaims.size()) + " claim(s) of its texts do not hold, first " +
                                 falseClaims.front().pointer + ": " + falseClaims.front().message);
        report.issues.insert(report.issues.end(), falseClaims.begin(), falseClaims.end());
    }

    if (std::string own = ownBandWarning(level, Catalog::builtin()); !own.empty())
        report.warnings.push_back(std::move(own));
    if (a.fix)
        for (std::string& change : fixRestFindings(item.file, *report.level))
            report.fixes.push_back(std::move(change));
    report.rest = checkRest(level);
    if (!report.rest->passed())
    {
        // Each body that moved or broke, located in the file, with the fix where one is clear.
        const std::vector<LevelIssue> findings = restIssues(level, Catalog::builtin(), *report.rest, item.file);
        std::string reason = report.rest->summary();
        if (!findings.empty())
            reason = "does not stand: " + std::to_string(findings.size()) + " bod" +
                     (findings.size() == 1 ? "y" : "ies") + " moved or broke, first " + findings.front().pointer +
                     " at " + std::to_string(findings.front().line) + ":" + std::to_string(findings.front().column) +
                     ": " + findings.front().message;
        report.reasons.push_back(reason);
        report.issues.insert(report.issues.end(), findings.begin(), findings.end());
    }
    if (report.rest->worstMassRatio.ratio > kMaxStackMassRatio)
    {
        // Box2D's guidance, not a law: a structure that stands the rest check stands.
        const std::string what = "stacks heavy on light (mass ratio " + shortest(report.rest->worstMassRatio.ratio) +
                                 ", Box2D advises at most 10: " + report.rest->worstMassRatio.heavier + " on " +
                                 report.rest->worstMassRatio.lighter + ")";
        if (report.rest->passed())
            report.warnings.push_back(what + "; it stands the rest check, but a hit may make it jitter");
        else
            report.reasons.push_back(what);
    }
    if (a.solve && report.rest->passed() && !level.pigs.empty()) // a sandbox scene without pigs has nothing to win
    {
        // A first estimate of difficulty and stars within seconds, from a few of the model player's runs; the
        // solver and the other runs refine it.
        StagedDifficulty player(level, a.playerRuns, a.threads);
        player.estimate(std::cerr);
        SolverOptions options;
        options.threads = a.threads;
        ProgressBar bar("solving " + level.id);
        options.progress = [&bar](std::size_t done, std::size_t total)
        {
            bar.update(done, total);
        };
        report.solution = solveLevel(level, Catalog::builtin(), options);
        bar.finish();
        if (!report.solution->outcome.won)
        {
            std::string left;
            for (const int pig : report.solution->survivingPigs)
            {
                left += (left.empty() ? ": " : "; ") + std::string("pig ") + std::to_string(pig) + " (" +
                        level.pigs[static_cast<std::size_t>(pig)].type + ")";
                if (const std::string why = whyPigSurvives(level, Catalog::builtin(), pig); !why.empty())
                    left += ", " + why;
            }
            report.reasons.push_back(
                "the solver found no win (best: " + std::to_string(report.solution->outcome.pigsRemaining) +
                " pig(s) left" + left + ")");
        }
        else if (report.solution->outcome.stars < 1)
            report.reasons.push_back("the solver's best win earns no star");
        if (a.playerRuns > 0 && report.solution->outcome.won)
            report.player = player.finish(std::cerr);
        if (report.solution->outcome.won)
        {
            report.recommendedStars =
                recommendedStars(report.player.value_or(PlayerDifficulty{}), report.solution->outcome.score);
            if (a.writeStars && *report.recommendedStars != level.starScores)
            {
                // Every other byte as it was; a file `abalike fmt` would leave alone stays so (the key where fmt puts
                // it, not appended at the end).
                const std::string text = readText(item.file);
                const std::string schema = schemaReferenceOf(text);
                std::string starred = withStars(text, *report.recommendedStars);
                if (writeLevelJson(level, schema) == text)
                {
                    LevelDef withNewStars = level;
                    withNewStars.starScores = *report.recommendedStars;
                    starred = writeLevelJson(withNewStars, schema);
                }
                writeFileAtomically(item.file, starred);
                report.starsWritten = true;
            }
        }
    }
    return report;
}

/// Ids must be unique across everything checked together (a campaign), or progress would mix levels up.
void checkUniqueIds(std::vector<FileReport>& reports)
{
    std::map<std::string, std::string> firstFile;
    for (FileReport& report : reports)
    {
        if (!report.level)
            continue;
        const auto [it, inserted] = firstFile.emplace(report.level->id, report.file);
        if (!inserted && it->second != report.file)
            report.reasons.push_back("id \"" + report.level->id + "\" is already used by " + it->second);
    }
}

std::string summaryLine(const FileReport& r)
{
    std::ostringstream line;
    line << (r.ok() ? "PASS " : "FAIL ") << r.file;
    if (!r.ok())
    {
        line << ": ";
        for (std::size_t i = 0; i < r.reasons.size(); ++i)
            line << (i ? "; " : "") << r.reasons[i];
        return line.str();
    }
    line << " (" << r.level->id << (r.level->sandbox ? ", sandbox scene" : "") << ", stands still";
    for (const std::string& warning : r.warnings)
        line << "; warning: " << warning;
    if (r.solution)
        line << "; solved: " << r.solution->outcome.score << " points, " << r.solution->outcome.stars << " star(s), "
             << r.solution->shots.size() << " shot(s)";
    if (r.player)
        line << "; " << playerDifficultyText(*r.player);
    if (r.recommendedStars)
    {
        const auto stars = [](const std::array<int, 3>& s)
        {
            return std::to_string(s[0]) + " / " + std::to_string(s[1]) + " / " + std::to_string(s[2]);
        };
        line << "; stars: recommended " << stars(*r.recommendedStars);
        if (r.starsWritten)
            line << ", written into the file";
        else if (*r.recommendedStars != r.level->starScores)
            line << ", the file has " << stars(r.level->starScores) << " (--write-stars writes them)";
        else
            line << ", as the file has";
    }
    line << ")";
    return line.str();
}

nlohmann::ordered_json reportJson(const FileReport& r)
{
    nlohmann::ordered_json out;
    out["file"] = r.file;
    out["ok"] = r.ok();
    out["level"] = r.level ? nlohmann::ordered_json(r.level->id) : nullptr;
    out["sandbox"] = r.level ? nlohmann::ordered_json(r.level->sandbox) : nullptr;
    nlohmann::ordered_json errors = nlohmann::ordered_json::array();
    for (const LevelIssue& issue : r.issues)
        errors.push_back({{"file", issue.file},
                          {"line", issue.line},
                          {"column", issue.column},
                          {"pointer", issue.pointer},
                          {"message", issue.message},
                          {"text", issue.format()}});
    out["errors"] = std::move(errors);
    if (r.rest)
        out["rest"] = {{"ok", r.rest->passed()},
                       {"seconds", r.rest->seconds},
                       {"max_move_m", r.rest->maxDisplacementM},
                       {"damaged", r.rest->damagedBodies},
                       {"destroyed", r.rest->destroyedBodies},
                       {"settled", r.rest->settled},
                       {"worst_mass_ratio", r.rest->worstMassRatio.ratio},
                       {"summary", r.rest->summary()}};
    else
        out["rest"] = nullptr;
    out["solve"] = r.solution ? solutionToJson(*r.level, *r.solution) : nlohmann::ordered_json(nullptr);
    out["player"] = r.player ? playerDifficultyJson(*r.player) : nlohmann::ordered_json(nullptr);
    out["recommended_stars"] = r.recommendedStars ? nlohmann::ordered_json(*r.recommendedStars) : nullptr;
    out["stars_written"] = r.starsWritten;
    out["reasons"] = r.reasons;
    out["warnings"] = r.warnings;
    out["fixes"] = r.fixes;
    return out;
}

/// The concept and the hints as the player reads them, their {...} values filled.
void printTexts(const LevelDef& level)
{
    const auto show = [&](const std::string& label, const std::string& text)
    {
        if (!text.empty())
            std::cout << "  " << label << ": " << escapeForTerminal(levelText(text, level, Catalog::builtin())) << '\n';
    };
    show("concept", level.lesson);
    for (std::size_t i = 0; i < level.hints.size(); ++i)
        show("hint " + std::to_string(i + 1), level.hints[i]);
}

/// Each --fill text with the level's {values} filled, as the game fills its texts. Throws UsageError saying which
/// text, where in it and what is wrong when one does not fill.
std::vector<std::string> filledTexts(const CheckArgs& a, const FileReport& r)
{
    std::vector<std::string> out;
    if (!r.level)
        return out;
    for (const std::string& text : a.fill)
    {
        try
        {
            out.push_back(fillText(text, *r.level, Catalog::builtin()));
        }
        catch (const TextValueError& e)
        {
            throw UsageError("--fill \"" + text + "\" at character " + std::to_string(e.offset() + 1) + " for " +
                             r.file + ": " + e.what());
        }
    }
    return out;
}

/// Every file the arguments name (a manifest: every level it lists), checked.
std::vector<FileReport> checkAll(const CheckArgs& a)
{
    std::vector<FileReport> reports;
    for (const CheckItem& item : expand(a.files, reports))
        reports.push_back(checkFile(item, a));
    checkUniqueIds(reports);
    return reports;
}

int runCheck(const CheckArgs& a)
{
    if (a.writeStars && !a.solve)
        throw UsageError("--write-stars: the stars come from the solver and the model player: add --solve");
    if (a.threads < 0 || a.threads > 256)
        throw UsageError("--threads: expected 0 (all cores) to 256, got " + std::to_string(a.threads));
    const std::vector<FileReport> reports = checkAll(a);
    bool allOk = true;
    for (const FileReport& r : reports)
        allOk = allOk && r.ok();
    if (a.json)
    {
        nlohmann::ordered_json out;
        out["ok"] = allOk;
        out["files"] = nlohmann::ordered_json::array();
        for (const FileReport& r : reports)
        {
            nlohmann::ordered_json file = reportJson(r);
            if (!a.fill.empty())
                file["filled"] = filledTexts(a, r);
            out["files"].push_back(std::move(file));
        }
        std::cout << out.dump(2) << '\n';
    }
    else
    {
        for (const FileReport& r : reports)
        {
            for (const std::string& change : r.fixes)
                std::cout << escapeForTerminal(change.rfind("not fixed: ", 0) == 0
                                                   ? "could not fix " + r.file + ": " + change.substr(11)
                                                   : "fixed " + r.file + ": " + change)
                          << '\n';
            std::cout << escapeForTerminal(summaryLine(r)) << '\n';
            if (a.texts && r.level)
                printTexts(*r.level);
            for (const std::string& filled : filledTexts(a, r))
                std::cout << "  fill: " << escapeForTerminal(filled) << '\n';
            // Every problem in the FILE:LINE:COL form editors jump to, on stderr like a compiler's.
            for (const LevelIssue& issue : r.issues)
                std::cerr << issue.format() << '\n';
        }
    }
    return allOk ? 0 : kUsageExitCode;
}

} // namespace

bool packPassesCheck(const std::string& manifest, std::ostream& out)
{
    CheckArgs args;
    args.files = {manifest};
    bool allOk = true;
    for (const FileReport& r : checkAll(args))
    {
        if (r.ok())
            continue;
        allOk = false;
        out << escapeForTerminal(summaryLine(r)) << '\n';
        for (const LevelIssue& issue : r.issues)
            out << issue.format() << '\n';
    }
    return allOk;
}

CommandRunner addCheckCommand(CLI::App& app)
{
    auto args = std::make_shared<CheckArgs>();
    CLI::App* cmd = app.add_subcommand(
        "check", "Check level files (or a campaign manifest: every level it lists): format, geometry, rest, solver");
    cmd->add_option("files", args->files, "level JSON files or campaign manifests")->required();
    cmd->add_flag("--json", args->json, "print one JSON report");
    cmd->add_flag("--solve", args->solve, "also run the solver: each level must be won with at least one star");
    cmd->add_option("--threads", args->threads, "solver worker threads (default 0: every core)");
    cmd->add_option("--player-runs", args->playerRuns,
                    "with --solve: plays of the model player, whose win rate is the level's difficulty (default 40; "
                    "0: none)");
    cmd->add_flag("--texts", args->texts,
                  "also print each level's concept and hints as the player reads them, their {...} values filled");
    cmd->add_option("--fill", args->fill,
                    "also print this text with its {...} values filled from each level, as the game fills its texts "
                    "(repeatable; a value that does not fill is a usage error)");
    cmd->add_flag("--write-stars", args->writeStars,
                  "with --solve: write the recommended star thresholds (from the model player's winning scores) "
                  "into each level file, every other byte as it was");
    cmd->add_flag("--fix", args->fix,
                  "make every verified fix of the rest test's findings (y of a body that floats or overlaps, x of one "
                  "past its supports' edge, angle_deg of one leaning on a corner), round after round, rewriting just "
                  "those numbers in the file; print each change and what could not be fixed, and why");
    return [args]
    {
        return runCheck(*args);
    };
}

} // namespace abalike::app
