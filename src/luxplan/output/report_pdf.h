// report.pdf: report.html printed by headless Chromium (Debian's chromium, installed
// by scripts/install-deps.sh) on A4 by the page's print stylesheet.
#pragma once

#include <atomic>
#include <filesystem>
#include <string>

namespace luxplan {

// The browser that prints: $LUXPLAN_CHROMIUM if set (a path or a name on PATH), else
// the first of chromium, chromium-browser, google-chrome on PATH. "" when none is found.
std::string pdfBrowser();

// Prints folder/report.html to folder/report.pdf: Chromium writes into a temporary
// folder of its own, then the PDF is written into `folder` atomically (a temporary
// name, then renamed). Returns "" on success, else why no report.pdf was written (no
// browser, it failed or ran past `timeoutSeconds`, `cancel` was set); it never throws
// but for an I/O error writing report.pdf itself (IoError).
std::string writeReportPdf(const std::filesystem::path& folder, double timeoutSeconds = 180,
                           const std::atomic<bool>* cancel = nullptr);

}  // namespace luxplan
