#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace abalike
{

/// Median wall time in seconds of one call of `work`, over `repeats` timed batches of `batch` calls each
/// (std::chrono::steady_clock). Batching keeps calls much shorter than a clock tick measurable.
template <class Work>
double medianSeconds(Work&& work, int repeats, int batch = 1)
{
    std::vector<double> samples;
    samples.reserve(static_cast<std::size_t>(repeats));
    for (int r = 0; r < repeats; ++r)
    {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < batch; ++i)
            work();
        const auto stop = std::chrono::steady_clock::now();
        samples.push_back(std::chrono::duration<double>(stop - start).count() / batch);
    }
    std::nth_element(samples.begin(), samples.begin() + static_cast<long>(samples.size() / 2), samples.end());
    return samples[samples.size() / 2];
}

} // namespace abalike
