#pragma once
// What a year has traced so far, kept on disk as it goes, so that an interrupted run (Ctrl-C, a
// killed process) goes on from there (`lucerna annual --resume`, the Annual dock's Compute after
// Cancel) with the same result: each point's coefficients depend only on its index and the seed.
// The file is keyed by everything the coefficients depend on (the scene's text and geometry, the
// points, the settings, the site's latitude and north), so that a stale one is never read; points
// are appended whole and flushed one by one, and a torn last one is dropped on reading.

#include "render/annual/daylight_coefficients.h"

#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace lucerna {

class AnnualCheckpoint {
public:
    // The file at `path` for a year of key `key`; nothing is read or written yet.
    AnnualCheckpoint(std::string path, uint64_t key) : path_(std::move(path)), key_(key) {}
    ~AnnualCheckpoint();

    // The points an earlier run of the same key traced (none when the file is missing, another
    // key's or unreadable); then the file is open for appending after them. Without `resume`
    // the file starts empty.
    std::map<size_t, PointCoefficients> open(bool resume);
    // Thread-safe; errors (a full disk) only stop the checkpoint, never the year.
    void append(size_t point, const PointCoefficients& c);
    // The year is complete: the file goes.
    void remove();
    const std::string& path() const { return path_; }

private:
    std::string path_;
    uint64_t key_;
    std::mutex mutex_;
    std::FILE* file_ = nullptr;
};

// The key: a 64-bit FNV-1a hash of what the coefficients depend on.
uint64_t annualCheckpointKey(const Scene& scene, const std::vector<V3d>& points, const V3d& normal, double latitudeDeg,
                             const std::string& settingsText);

}  // namespace lucerna
