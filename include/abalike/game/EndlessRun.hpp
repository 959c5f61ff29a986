#pragma once

namespace abalike
{

/// The endless mode's rules: a run of generated levels whose difficulty follows the player. The difficulty is the
/// loss share the generator is asked for (the share of the model player's tries that lose): one step up after a
/// win, one step down after a loss. A loss also ends the run; the next level starts a new one.
class EndlessRun
{
public:
    /// Loss shares in tenths: a run starts at 0.3 and stays within 0.1 to 0.9, where the generator finds levels.
    static constexpr int kStartTenths = 3;
    static constexpr int kMinTenths = 1;
    static constexpr int kMaxTenths = 9;

    /// What a run achieved when it ended.
    struct Result
    {
        int levelsWon = 0;
        int score = 0;
    };

    explicit EndlessRun(int lossShareTenths = kStartTenths);

    /// The loss share of the next level: tenths() / 10, exactly 0.1, 0.2, ... 0.9.
    double lossShare() const { return m_tenths / 10.0; }
    int lossShareTenths() const { return m_tenths; }
    /// The loss shares the level after the next may need, the likelier first: after a win, then after a loss.
    int tenthsAfterWin() const;
    int tenthsAfterLoss() const;

    int levelsWon() const { return m_levelsWon; }
    int score() const { return m_score; }

    /// The level was won with `levelScore` points: the run goes on, one step harder.
    void won(int levelScore);
    /// The level was lost: returns what the run achieved and starts a new run, one step easier.
    Result lost();

private:
    int m_tenths;
    int m_levelsWon = 0;
    int m_score = 0;
};

} // namespace abalike
