// cv_peer.cpp - OpenCV's template matching behind the C interface of cv_peer.h.
#include "cv_peer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

struct cv_peer_image {
    cv::Mat mat;  // CV_8UC1 (wrapping the view) or CV_32FC1 (a converted copy)
};

extern "C" void cv_peer_init(char *info, size_t infolen)
{
    cv::setNumThreads(1);
    std::snprintf(info, infolen, "OpenCV %s, %d thread(s), IPP %s, %s", CV_VERSION,
                  cv::getNumThreads(), cv::ipp::useIPP() ? "on" : "off",
                  cv::useOptimized() ? "optimised SIMD dispatch on" : "optimisations off");
}

extern "C" cv_peer_image_t *cv_peer_image_new(const ssda_view_t *v)
{
    cv_peer_image_t *img = new (std::nothrow) cv_peer_image_t;
    if (img == nullptr) {
        return nullptr;
    }
    try {
        if (v->format == SSDA_PIX_U8) {
            img->mat = cv::Mat(v->height, v->width, CV_8UC1, const_cast<void *>(v->data),
                               v->stride);
        } else {
            // 16-bit: matchTemplate has no 16-bit path; float32 holds every
            // 16-bit value exactly. Converted once, outside timed regions.
            cv::Mat src(v->height, v->width, CV_16UC1, const_cast<void *>(v->data), v->stride);
            src.convertTo(img->mat, CV_32F);
        }
    } catch (const cv::Exception &e) {
        std::fprintf(stderr, "cv_peer: %s\n", e.what());
        delete img;
        return nullptr;
    }
    return img;
}

extern "C" void cv_peer_image_free(cv_peer_image_t *img)
{
    delete img;
}

extern "C" int cv_peer_match(const cv_peer_image_t *img, const cv_peer_image_t *tmpl,
                             const cv_peer_job_t *jobs, size_t n, uint16_t win_w,
                             uint16_t win_h, uint16_t area_w, uint16_t area_h, int method,
                             uint16_t *best_x, uint16_t *best_y)
{
    const int cv_method = method == CV_PEER_SQDIFF ? cv::TM_SQDIFF : cv::TM_CCOEFF_NORMED;
    cv::Mat result;
    try {
        for (size_t k = 0; k < n; k++) {
            cv::Mat area = img->mat(cv::Rect(jobs[k].ax, jobs[k].ay, area_w, area_h));
            cv::Mat window = tmpl->mat(cv::Rect(jobs[k].wx, jobs[k].wy, win_w, win_h));
            cv::Point lo, hi;
            cv::matchTemplate(area, window, result, cv_method);
            cv::minMaxLoc(result, nullptr, nullptr, &lo, &hi);
            const cv::Point &best = cv_method == cv::TM_SQDIFF ? lo : hi;
            best_x[k] = (uint16_t)best.x;
            best_y[k] = (uint16_t)best.y;
        }
    } catch (const cv::Exception &e) {
        std::fprintf(stderr, "cv_peer: %s\n", e.what());
        return -1;
    }
    return 0;
}

extern "C" int cv_peer_ccoeff_scores(const cv_peer_image_t *img, const cv_peer_image_t *tmpl,
                                     const cv_peer_job_t *job, uint16_t win_w, uint16_t win_h,
                                     uint16_t area_w, uint16_t area_h, uint16_t *best_x,
                                     uint16_t *best_y, double *best, double *second)
{
    cv::Mat result;
    try {
        cv::Mat area = img->mat(cv::Rect(job->ax, job->ay, area_w, area_h));
        cv::Mat window = tmpl->mat(cv::Rect(job->wx, job->wy, win_w, win_h));
        cv::Point hi;
        double vmax = 0.0, v2 = -2.0;
        cv::matchTemplate(area, window, result, cv::TM_CCOEFF_NORMED);
        cv::minMaxLoc(result, nullptr, &vmax, nullptr, &hi);
        for (int y = 0; y < result.rows; y++) {
            for (int x = 0; x < result.cols; x++) {
                if (std::abs(x - hi.x) <= 1 && std::abs(y - hi.y) <= 1) {
                    continue;
                }
                v2 = std::max(v2, (double)result.at<float>(y, x));
            }
        }
        *best_x = (uint16_t)hi.x;
        *best_y = (uint16_t)hi.y;
        *best = vmax;
        *second = v2;
    } catch (const cv::Exception &e) {
        std::fprintf(stderr, "cv_peer: %s\n", e.what());
        return -1;
    }
    return 0;
}
