#include <abalike/game/EndlessRun.hpp>

#include <algorithm>
#include <limits>

namespace abalike
{

EndlessRun::EndlessRun(int lossShareTenths) : m_tenths(std::clamp(lossShareTenths, kMinTenths, kMaxTenths)) {}

int EndlessRun::tenthsAfterWin() const
{
    return std::min(m_tenths + 1, kMaxTenths);
}

int EndlessRun::tenthsAfterLoss() const
{
    return std::max(m_tenths - 1, kMinTenths);
}

void EndlessRun::won(int levelScore)
{
    m_tenths = tenthsAfterWin();
    ++m_levelsWon;
    // Scores are ints in the progress file: a very long run stops counting rather than wrapping.
    const int add = std::max(levelScore, 0);
    m_score = m_score > std::numeric_limits<int>::max() - add ? std::numeric_limits<int>::max() : m_score + add;
}

EndlessRun::Result EndlessRun::lost()
{
    const Result result{m_levelsWon, m_score};
    m_tenths = tenthsAfterLoss();
    m_levelsWon = 0;
    m_score = 0;
    return result;
}

} // namespace abalike
