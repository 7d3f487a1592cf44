// The one table of sampler types: a new type is its file and one line here.
#include <luxplan/core/names.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {

std::shared_ptr<const SamplerType> readPlanarSampler(const json::Fields& f);       // planar.cpp
std::shared_ptr<const SamplerType> readDirectionalSampler(const json::Fields& f);  // directional.cpp
std::shared_ptr<const SamplerType> readVolumeSampler(const json::Fields& f);       // volume.cpp
std::shared_ptr<const SamplerType> readCylindricalSampler(const json::Fields& f);  // cylindrical.cpp
std::shared_ptr<const SamplerType> readUgrSampler(const json::Fields& f);          // ugr.cpp
std::shared_ptr<const SamplerType> readDgpSampler(const json::Fields& f);          // dgp.cpp

const std::vector<SamplerTypeEntry>& samplerTypes() {
    static const std::vector<SamplerTypeEntry> types = {
        {"planar", readPlanarSampler},
        {"directional", readDirectionalSampler},
        {"volume", readVolumeSampler},
        {"cylindrical", readCylindricalSampler},
        {"ugr", readUgrSampler},
        {"dgp", readDgpSampler},
    };
    return types;
}

const SamplerTypeEntry* findSamplerType(std::string_view name) { return findByName(samplerTypes(), name); }
std::vector<std::string> samplerTypeNames() { return namesOf(samplerTypes()); }

}  // namespace luxplan
