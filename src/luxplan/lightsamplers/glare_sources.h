// Glare metrics shared by the "ugr" and "dgp" samplers (docs/glare.md): the Guth
// position index as evalglare codes it, UGR (CIE 117-1995) and DGP (Wienold and
// Christoffersen 2006, evalglare's constants), and the placed sampler both use: the
// vertical illuminance at the eye and a direct view of each source (luminaire, sun
// disk), each source's visible solid angle omega, mean luminance L and direction.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include <luxplan/scene/sampler_result.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {

// P from tau (the angle between the vertical plane through the line of sight and the
// plane holding the line of sight and the source; 0 straight above) and sigma (the
// angle between the line of sight and the source), in degrees; capped at 16.
double guthIndex(double tauDeg, double sigmaDeg);
// P of the unit direction `w` seen along unit `forward` with world up +z: Guth above
// the line of sight, Iwata's formula (evalglare's) below it; 16 behind the eye.
double guthIndexOf(const Vec3& forward, const Vec3& w);

// 8 log10(0.25 / Lb * sum L^2 omega / P^2), 0 with no source (and never below 0).
double unifiedGlareRating(double backgroundLuminance, const std::vector<GlareSource>& sources);
// 5.87e-5 Ev + 0.159 + 0.092 log10(1 + sum L^2 omega / (P^2 Ev^1.87)), times the
// low-light factor below 1000 lx, clamped to [0, 1].
double daylightGlareProbability(double verticalIlluminance, const std::vector<GlareSource>& sources);

// The hemisphere in front of an eye as n x n cells of equal solid angle 2 pi / n^2:
// the unit square's grid through equalAreaHemisphere (core/warp.h), local x to the
// eye's right, y up, z along the line of sight. Cells that are neighbours in the
// square are neighbours on the hemisphere; with n even, the horizontal plane through
// the line of sight runs along cell edges.
class DirectionGrid {
public:
    explicit DirectionGrid(int cellsPerSide);
    int cellsPerSide() const { return n_; }
    int cells() const { return n_ * n_; }
    double cellSolidAngle() const { return 2 * kPi / (double(n_) * n_); }
    // A direction of cell c (row-major, right fastest), uniform over it for uniform u.
    Vec3 direction(int cell, Vec2 u) const;
    // The mean of the cell's unit directions (length < 1): its z is the mean cosine.
    const Vec3& centroid(int cell) const { return centroids_[size_t(cell)]; }

private:
    int n_;
    std::vector<Vec3> centroids_;
};

// The eye's frame: right, up (world +z made orthogonal to the line of sight) and forward.
Frame eyeFrame(const Vec3& forward);

// The placed "ugr" or "dgp" sampler. Items: 0 the vertical illuminance at the eye,
// then per source slot (every luminaire of the scene, then, for DGP, every sun disk:
// setSources) its visible solid angle, L omega, direct vertical illuminance and
// omega-weighted direction; then, for DGP, each cell of its direction grid: the mean
// luminance through the cell but for the luminaires and sun disks (surveyed by their
// slots). Cells brighter than the threshold, joined to their eight neighbours, are the
// region sources.
class PlacedGlare final : public PlacedSampler {
public:
    static constexpr int kQuantities = 6;
    enum class Metric { Ugr, Dgp };
    PlacedGlare(Metric metric, Vec3 eye, Vec3 forward, double thresholdNits,
                std::shared_ptr<const DirectionGrid> grid = nullptr)
        : metric_(metric), eye_(eye), forward_(forward), frame_(eyeFrame(forward)), threshold_(thresholdNits),
          grid_(std::move(grid)) {}

    void setSources(int luminaires, int sunDisks) override {
        luminaires_ = luminaires;
        slots_ = luminaires + (metric_ == Metric::Dgp ? sunDisks : 0);
    }
    // The first direction cell's item.
    int firstCell() const { return 1 + slots_ * kQuantities; }
    int items() const override { return firstCell() + (grid_ ? grid_->cells() : 0); }
    void sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, const PathParams& params,
                PathContributions& out) const override;
    // The metric from all folds; its error by the jackknife over the folds.
    Estimate combine(const ItemEstimates& items) const override;
    // Adaptive measurement stops the cells that are surely below the threshold (their
    // upper bound is): they are no source and E_v is item 0's.
    std::vector<char> stillNeeded(const ItemEstimates& items, double z, double targetMin, double targetMax) const override;
    SamplerDrawing drawing() const override;
    // The survey from item means (points of a SamplerResult, in item order).
    std::optional<GlareSurvey> survey(const std::vector<double>& itemMeans) const override { return surveyOf(itemMeans); }
    GlareSurvey surveyOf(const std::vector<double>& itemMeans) const;

private:
    void sampleSlot(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, const PathParams& params,
                    PathContributions& out) const;
    // The connected regions of cells brighter than the threshold, as sources; adds
    // their direct vertical illuminance to `direct`.
    void addRegions(const std::vector<double>& itemMeans, std::vector<GlareSource>& sources, double& direct) const;

    Metric metric_;
    Vec3 eye_, forward_;
    Frame frame_;  // s right, t up, n forward
    double threshold_;
    std::shared_ptr<const DirectionGrid> grid_;  // DGP only
    int luminaires_ = 0, slots_ = 0;
};

// What the "ugr" and "dgp" types share: their eye surveys sources, their value is
// its own unit, and their details are the survey (report.json's "glare").
class GlareSamplerType : public SamplerType {
public:
    bool surveysSources() const override { return true; }
    ResultGroup resultGroup() const override { return ResultGroup::Glare; }
    // {"glare": {"vertical_illuminance", "direct_illuminance", "background_luminance",
    // "sources": [{"kind", "slot" or "region", "direction", "luminance", "solid_angle",
    // "position_index"}]}}, where the result has a survey.
    void addDetails(const SamplerResult& result, nlohmann::ordered_json& out) const override;
    // "UGR 13.2, Lb 31.0 cd/m2, 1 source; luminaire [0.00 0.71 0.71] L 5200 cd/m2,
    // omega 1.234 msr, P 2.10" ("DGP 0.352, Ev 2100 lx, ..." for DGP); "" without a survey.
    std::string detailsText(const SamplerResult& result) const override;

protected:
    // The text's head before the sources: "UGR 13.2, Lb 31.0 cd/m2".
    virtual std::string surveyHead(double value, const GlareSurvey& survey) const = 0;
};

// Constructed in C++ (tests): a normalized direction, which must not be zero.
std::shared_ptr<const SamplerType> ugrSampler(Vec3 origin, Vec3 direction);
// `directionCells`: the direction grid's cells per side (the file's "direction_cells").
std::shared_ptr<const SamplerType> dgpSampler(Vec3 origin, Vec3 direction, double sourceThresholdNits = 2000,
                                              int directionCells = 24);

}  // namespace luxplan
