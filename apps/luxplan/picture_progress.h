// What `render`, `report` and `optimize` say on stderr while they make the pictures:
// each long step as it begins, and render.png's progress every two seconds.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include <luxplan/output/outputs.h>

namespace luxplan::cli {

class PictureProgress {
public:
    // Hooks into `options` (onStep, renderRowsDone); must outlive the writeRunOutputs call.
    explicit PictureProgress(OutputOptions& options);
    ~PictureProgress();
    PictureProgress(const PictureProgress&) = delete;
    PictureProgress& operator=(const PictureProgress&) = delete;

private:
    void watch();

    int rows_;
    std::atomic<int> rowsDone_{0};
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::chrono::steady_clock::time_point renderStart_{};
    bool rendering_ = false;
    std::thread watcher_;
};

}  // namespace luxplan::cli
