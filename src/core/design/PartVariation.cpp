#include <abalike/design/PartVariation.hpp>

#include "edit/EditHelpers.hpp"

#include <algorithm>
#include <cmath>

namespace abalike
{

namespace
{

/// Whether a block's angle is a whole number of quarter turns, and whether that turn lays it on its side.
bool quarterTurn(double angleDeg, bool& onSide)
{
    const double turns = angleDeg / 90.0;
    if (std::abs(turns - std::round(turns)) > kSameEdgeM)
        return false;
    onSide = (static_cast<long>(std::round(turns)) % 2) != 0;
    return true;
}

/// Mirroring turns a right triangle into its mirror image only when its legs are equal (then it is the same triangle
/// a quarter turn on); any other shape mirrors as it is.
bool canMirror(const LevelDef& part)
{
    return std::none_of(part.blocks.begin(), part.blocks.end(),
                        [](const BlockDef& b)
                        { return b.shape == BlockShape::Triangle && std::abs(b.widthM - b.heightM) > kSameEdgeM; });
}

bool allWood(const LevelDef& part)
{
    return !part.blocks.empty() &&
           std::all_of(part.blocks.begin(), part.blocks.end(), [](const BlockDef& b) { return b.material == "wood"; });
}

double pigRadius(const Catalog& catalog, const std::string& type)
{
    const PigType* pig = catalog.findPig(type);
    return pig != nullptr ? pig->radiusM : 0.25;
}

/// The pig's centre once it is of another type, resting on what it rested on (its lowest point stays).
double restingY(const PigDef& pig, const std::string& type, const Catalog& catalog)
{
    return pig.y - pigRadius(catalog, pig.type) + pigRadius(catalog, type);
}

/// Whether a pig of that type, resting where the pig rests, stays clear of the part's blocks (their bounds; touching
/// is clear).
bool fitsAs(const LevelDef& part, const PigDef& pig, const std::string& type, const Catalog& catalog)
{
    const double r = pigRadius(catalog, type);
    const double y = restingY(pig, type, catalog);
    return std::none_of(part.blocks.begin(), part.blocks.end(),
                        [&](const BlockDef& b)
                        {
                            const auto box = objectBounds(ObjectDef(b), catalog);
                            const double dx = std::max({box[0].x - pig.x, 0.0, pig.x - box[1].x});
                            const double dy = std::max({box[0].y - y, 0.0, y - box[1].y});
                            return dx * dx + dy * dy < (r - kSameEdgeM) * (r - kSameEdgeM);
                        });
}

/// The type a pig becomes: small and medium pigs the other size on a coin's heads, any other as it is. (Helmet pigs,
/// four times as hard to break, made most levels too hard for their birds.)
std::string pigTypeFor(const std::string& type, bool heads)
{
    if (!heads || (type != "small" && type != "medium"))
        return type;
    return type == "small" ? "medium" : "small";
}

} // namespace

PartSpan partSpan(const LevelDef& part, const Catalog& catalog)
{
    PartSpan s;
    for (const BlockDef& b : part.blocks)
    {
        const auto box = objectBounds(ObjectDef(b), catalog);
        s.left = std::min(s.left, box[0].x);
        s.right = std::max(s.right, box[1].x);
    }
    for (const PigDef& p : part.pigs)
    {
        const auto box = objectBounds(ObjectDef(p), catalog);
        s.left = std::min(s.left, box[0].x);
        s.right = std::max(s.right, box[1].x);
    }
    return s;
}

double tidyMetres(double metres)
{
    return std::round(metres * 1e4) / 1e4;
}

PartVariation drawPartVariation(const LevelDef& part, GeneratorRng& rng, const Catalog& catalog)
{
    const double width = partSpan(part, catalog).width();
    std::vector<double> stretches;
    for (const double s : kPartStretches)
        if (s == 1.0 || width * s <= kMaxStretchedWidthM + kSameEdgeM)
            stretches.push_back(s);
    // Every draw is made whatever the part allows: the seed's next draws stay where they were.
    const double stretch = stretches[rng.index(stretches.size())];
    const bool mirror = rng.coin();
    const bool ice = rng.index(4) == 0;
    PartVariation v;
    v.stretch = stretch;
    v.mirror = mirror && canMirror(part);
    v.ice = ice && allWood(part);
    for (const PigDef& pig : part.pigs)
    {
        const std::string type = pigTypeFor(pig.type, rng.coin());
        v.pigTypes.push_back(fitsAs(part, pig, type, catalog) ? type : pig.type);
    }
    return v;
}

LevelDef varyPart(const LevelDef& part, const PartVariation& variation, const Catalog& catalog)
{
    const double middle = partSpan(part, catalog).middle();
    const double s = variation.stretch;
    const auto place = [&](double x)
    {
        const double offset = (variation.mirror ? middle - x : x - middle) * s;
        return tidyMetres(middle + offset);
    };
    LevelDef varied = part;
    for (BlockDef& b : varied.blocks)
    {
        b.x = place(b.x);
        if (variation.mirror)
            b.angleDeg = b.shape == BlockShape::Triangle ? 90.0 - b.angleDeg : -b.angleDeg;
        if (b.angleDeg == 0.0)
            b.angleDeg = 0.0; // -0 reads as 0 in the file
        bool onSide = false;
        // Floors, planks, cages and square blocks widen with the spacing; posts and circles keep their size.
        if (b.shape != BlockShape::Circle && quarterTurn(b.angleDeg, onSide))
        {
            double& across = onSide ? b.heightM : b.widthM;
            const double along = onSide ? b.widthM : b.heightM;
            if (across >= along - kSameEdgeM)
                across = tidyMetres(across * s);
        }
        if (variation.ice && b.material == "wood")
            b.material = "ice";
    }
    for (std::size_t i = 0; i < varied.pigs.size(); ++i)
    {
        PigDef& p = varied.pigs[i];
        p.x = place(p.x);
        if (i < variation.pigTypes.size() && variation.pigTypes[i] != p.type)
        {
            p.y = tidyMetres(restingY(p, variation.pigTypes[i], catalog));
            p.type = variation.pigTypes[i];
        }
    }
    return varied;
}

} // namespace abalike
