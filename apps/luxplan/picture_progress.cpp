// The pictures' progress on stderr: one line per step, and while render.png is traced
// a line every two seconds with its share done and the time left.
#include "picture_progress.h"

#include <cstdio>

#include <luxplan/optimizer/progress_line.h>

namespace luxplan::cli {

PictureProgress::PictureProgress(OutputOptions& options) : rows_(std::max(1, options.renderHeight)) {
    options.renderRowsDone = &rowsDone_;
    options.onStep = [this](const std::string& step) {
        std::lock_guard lock(mutex_);
        std::fprintf(stderr, "  pictures: %s\n", step.c_str());
        rendering_ = step.rfind("rendering", 0) == 0;
        if (rendering_) renderStart_ = std::chrono::steady_clock::now(), rowsDone_.store(0);
    };
    watcher_ = std::thread([this] { watch(); });
}

PictureProgress::~PictureProgress() {
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_all();
    watcher_.join();
}

void PictureProgress::watch() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::seconds(2), [this] { return done_; })) {
        if (!rendering_) continue;
        const int done = rowsDone_.load();
        if (done <= 0 || done >= rows_) continue;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart_).count();
        const double left = elapsed * (rows_ - done) / done;
        std::fprintf(stderr, "  pictures: render.png %d%% (%s left)\n", 100 * done / rows_, durationText(left).c_str());
    }
}

}  // namespace luxplan::cli
