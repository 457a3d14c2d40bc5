// libcamera camera (the Raspberry Pi camera): C++ inside, the rl_cam C
// interface outside. The camera streams YUV420; its Y plane is the grey
// image, lent straight from the mmapped buffer (no copy). Requests are
// queued once at start and re-queued on release, so grabbing allocates
// nothing. Exposure and gain: automatic (AeEnable), or manual
// (ExposureTime, AnalogueGain) as configured. The capture time is the
// request's SensorTimestamp (CLOCK_MONOTONIC, as rl_clock). Built only
// where libcamera is found, as the module ringloc-libcamera.so that
// cam_libcamera_load.c loads on first use (hal/CMakeLists.txt); its two
// entry points are all it exports.
#include <libcamera/libcamera.h>
#include <sys/mman.h>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <vector>

extern "C" {
#include "cam_libcamera.h"
#include "rl_cam.h"
}

using namespace libcamera;

namespace {

struct Mapped {
    void *addr;
    size_t len;
    const uint8_t *y; // the Y plane in the mapping
};

struct State {
    std::unique_ptr<CameraManager> cm;
    std::shared_ptr<Camera> camera;
    std::unique_ptr<CameraConfiguration> config;
    std::unique_ptr<FrameBufferAllocator> alloc;
    std::vector<std::unique_ptr<Request>> requests;
    std::vector<Mapped> maps; // by request index
    Stream *stream = nullptr;
    int width = 0, height = 0, stride = 0;
    std::mutex m;
    std::condition_variable cv;
    std::deque<Request *> done; // completed, not yet grabbed
    bool failed = false;
    long index = 0;

    void completed(Request *r)
    {
        std::lock_guard<std::mutex> lock(m);
        if (r->status() == Request::RequestCancelled)
            return;
        if (r->status() != Request::RequestComplete)
            failed = true;
        done.push_back(r);
        cv.notify_one();
    }

    ~State()
    {
        if (camera) {
            camera->stop();
            camera->requestCompleted.disconnect(this);
        }
        for (auto &mp : maps)
            if (mp.addr != MAP_FAILED && mp.addr != nullptr)
                munmap(mp.addr, mp.len);
        requests.clear();
        alloc.reset();
        if (camera) {
            camera->release();
            camera.reset();
        }
        if (cm)
            cm->stop();
    }
};

rl_err lc_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    State *s = static_cast<State *>(c->state);
    std::unique_lock<std::mutex> lock(s->m);
    if (!s->cv.wait_for(lock, std::chrono::milliseconds(timeout_ms), [s] { return !s->done.empty(); }))
        return RL_ETIMEOUT;
    if (s->failed)
        return RL_EIO;
    Request *r = s->done.front();
    s->done.pop_front();
    int slot = static_cast<int>(r->cookie());
    f->slot = slot;
    f->index = s->index++;
    f->t_us = rl_clock_now_us(); // without a stamp: now, the frame's end
    f->stamp = RL_CAM_STAMP_FRAME_END;
    {
        const FrameBuffer *b = r->buffers().begin()->second;
        std::optional<int64_t> sensor = r->metadata().get(controls::SensorTimestamp);
        std::optional<int32_t> exposure = r->metadata().get(controls::ExposureTime);
        // monotonic ns; on a Raspberry Pi both are the frame-start interrupt's: the
        // first row read, its exposure over
        if (sensor && *sensor > 0) {
            f->t_us = static_cast<uint64_t>(*sensor) / 1000u;
            f->stamp = RL_CAM_STAMP_FRAME_START;
        } else if (b->metadata().timestamp > 0) {
            f->t_us = b->metadata().timestamp / 1000u;
            f->stamp = RL_CAM_STAMP_FRAME_START;
        }
        if (exposure && *exposure > 0)
            f->exposure_us = *exposure;
    }
    f->img = rl_image_view(s->width, s->height, s->stride, const_cast<uint8_t *>(s->maps[slot].y));
    return RL_OK;
}

void lc_release(rl_cam *c, rl_cam_frame *f)
{
    State *s = static_cast<State *>(c->state);
    Request *r = s->requests[f->slot].get();
    r->reuse(Request::ReuseBuffers);
    s->camera->queueRequest(r);
}

void lc_close(rl_cam *c)
{
    delete static_cast<State *>(c->state);
}

const rl_cam_ops lc_ops = {lc_grab, lc_release, lc_close};

rl_err fail(rl_cam *c, State *s, char *err, size_t errlen, rl_err e, const char *what)
{
    std::snprintf(err, errlen, "libcamera camera %s: %s", c->name, what);
    delete s;
    c->state = nullptr;
    c->ops = nullptr;
    return e;
}

} // namespace

extern "C" RL_MODULE_EXPORT unsigned long rl_module_abi(void)
{
    return RL_CAM_LIBCAMERA_ABI;
}

extern "C" RL_MODULE_EXPORT rl_err rl_cam_libcamera_open(rl_cam *c, const rl_cam_config *cc, char *err,
                                                         size_t errlen)
{
    /* libcamera logs every camera manager start at INFO; the run loop
     * reopens with backoff and rate-limits its own lines, so keep
     * libcamera's quiet unless the user asked otherwise */
    setenv("LIBCAMERA_LOG_LEVELS", "*:ERROR", 0);
    State *s = new (std::nothrow) State;
    if (s == nullptr)
        return RL_ENOMEM;
    s->cm = std::make_unique<CameraManager>();
    if (s->cm->start() != 0)
        return fail(c, s, err, errlen, RL_ENODEV, "cannot start the camera manager");
    auto cams = s->cm->cameras();
    size_t which = cc->device && *cc->device ? std::strtoul(cc->device, nullptr, 10) : 0;
    if (cams.empty() || which >= cams.size())
        return fail(c, s, err, errlen, RL_ENOTFOUND, cams.empty() ? "no camera found" : "no camera of that index");
    s->camera = cams[which];
    if (s->camera->acquire() != 0)
        return fail(c, s, err, errlen, RL_ENODEV, "camera is in use by another program");
    s->config = s->camera->generateConfiguration({StreamRole::Viewfinder});
    if (!s->config || s->config->empty())
        return fail(c, s, err, errlen, RL_EUNSUPPORTED, "no stream configuration");
    StreamConfiguration &sc = s->config->at(0);
    sc.pixelFormat = formats::YUV420;
    if (cc->width > 0 && cc->height > 0)
        sc.size = Size(static_cast<unsigned>(cc->width), static_cast<unsigned>(cc->height));
    sc.bufferCount = 4;
    if (s->config->validate() == CameraConfiguration::Invalid || sc.pixelFormat != formats::YUV420)
        return fail(c, s, err, errlen, RL_EUNSUPPORTED, "does not stream YUV420");
    if ((cc->width && static_cast<int>(sc.size.width) != cc->width) ||
        (cc->height && static_cast<int>(sc.size.height) != cc->height)) {
        char what[128];
        std::snprintf(what, sizeof what, "gives %ux%u, not the configured %dx%d", sc.size.width,
                      sc.size.height, cc->width, cc->height);
        return fail(c, s, err, errlen, RL_EUNSUPPORTED, what);
    }
    if (s->camera->configure(s->config.get()) != 0)
        return fail(c, s, err, errlen, RL_EIO, "cannot configure");
    s->stream = sc.stream();
    s->width = static_cast<int>(sc.size.width);
    s->height = static_cast<int>(sc.size.height);
    s->stride = static_cast<int>(sc.stride);
    s->alloc = std::make_unique<FrameBufferAllocator>(s->camera);
    if (s->alloc->allocate(s->stream) < 0)
        return fail(c, s, err, errlen, RL_ENOMEM, "cannot allocate buffers");
    const auto &buffers = s->alloc->buffers(s->stream);
    for (size_t i = 0; i < buffers.size(); i++) {
        const FrameBuffer::Plane &y = buffers[i]->planes()[0];
        Mapped mp;
        std::unique_ptr<Request> r = s->camera->createRequest(i);
        if (!r || r->addBuffer(s->stream, buffers[i].get()) != 0)
            return fail(c, s, err, errlen, RL_EIO, "cannot create requests");
        /* map the whole dmabuf from 0 so the plane offset stays valid */
        mp.len = y.offset + y.length;
        mp.addr = mmap(nullptr, mp.len, PROT_READ, MAP_SHARED, y.fd.get(), 0);
        if (mp.addr == MAP_FAILED)
            return fail(c, s, err, errlen, RL_EIO, "cannot map buffers");
        mp.y = static_cast<const uint8_t *>(mp.addr) + y.offset;
        s->maps.push_back(mp);
        s->requests.push_back(std::move(r));
    }
    ControlList ctrls(controls::controls);
    const ControlInfoMap &offered = s->camera->controls();
    if (cc->exposure_us > 0 || cc->gain > 0) {
        if (offered.find(&controls::AeEnable) != offered.end())
            ctrls.set(controls::AeEnable, false);
        if (cc->exposure_us > 0) {
            if (offered.find(&controls::ExposureTime) == offered.end())
                return fail(c, s, err, errlen, RL_EUNSUPPORTED, "offers no ExposureTime control");
            ctrls.set(controls::ExposureTime, static_cast<int32_t>(cc->exposure_us));
        }
        if (cc->gain > 0) {
            if (offered.find(&controls::AnalogueGain) == offered.end())
                return fail(c, s, err, errlen, RL_EUNSUPPORTED, "offers no AnalogueGain control");
            ctrls.set(controls::AnalogueGain, static_cast<float>(cc->gain));
        }
    } else if (offered.find(&controls::AeEnable) != offered.end()) {
        ctrls.set(controls::AeEnable, true);
    }
    s->camera->requestCompleted.connect(s, &State::completed);
    if (s->camera->start(&ctrls) != 0)
        return fail(c, s, err, errlen, RL_EIO, "cannot start streaming");
    for (auto &r : s->requests)
        s->camera->queueRequest(r.get());
    c->state = s;
    c->ops = &lc_ops;
    char ex[48], ga[48];
    if (cc->exposure_us > 0)
        std::snprintf(ex, sizeof ex, "exposure %d us", cc->exposure_us);
    else
        std::snprintf(ex, sizeof ex, "exposure auto");
    if (cc->gain > 0)
        std::snprintf(ga, sizeof ga, "gain %g", cc->gain);
    else
        std::snprintf(ga, sizeof ga, "gain auto");
    std::snprintf(c->info, sizeof c->info, "libcamera %s, YUV420 %dx%d lent as is, %s, %s",
                  s->camera->id().c_str(), s->width, s->height, ex, ga);
    return RL_OK;
}

extern "C" RL_MODULE_EXPORT rl_err rl_cam_libcamera_probe(const rl_cam_config *cc, rl_cam_line_fn line,
                                                          void *ctx, char *err, size_t errlen)
{
    setenv("LIBCAMERA_LOG_LEVELS", "*:ERROR", 0);
    CameraManager cm;
    if (cm.start() != 0) {
        std::snprintf(err, errlen, "libcamera: cannot start the camera manager");
        return RL_ENODEV;
    }
    auto cams = cm.cameras();
    size_t which = cc->device && *cc->device ? std::strtoul(cc->device, nullptr, 10) : 0;
    char text[512];
    if (cams.empty() || which >= cams.size()) {
        std::snprintf(err, errlen, "libcamera camera %s: %s", cc->device ? cc->device : "0",
                      cams.empty() ? "no camera found" : "no camera of that index");
        cm.stop();
        return RL_ENOTFOUND;
    }
    for (size_t i = 0; i < cams.size(); i++) {
        std::snprintf(text, sizeof text, "libcamera camera %zu: %s%s", i, cams[i]->id().c_str(),
                      i == which ? " (configured)" : "");
        line(ctx, text);
    }
    {
        std::shared_ptr<Camera> cam = cams[which];
        std::unique_ptr<CameraConfiguration> conf = cam->generateConfiguration({StreamRole::Viewfinder});
        line(ctx, "formats (* ringloc takes it):");
        if (conf && !conf->empty()) {
            const StreamFormats &fm = conf->at(0).formats();
            for (const PixelFormat &pf : fm.pixelformats()) {
                SizeRange r = fm.range(pf);
                std::snprintf(text, sizeof text, "  %c %-10s %s", pf == formats::YUV420 ? '*' : ' ',
                              pf.toString().c_str(), r.toString().c_str());
                line(ctx, text);
            }
        }
        line(ctx, "controls:");
        for (const auto &kv : cam->controls()) {
            std::snprintf(text, sizeof text, "  control %-32s %s", kv.first->name().c_str(),
                          kv.second.toString().c_str());
            line(ctx, text);
        }
    }
    cams.clear();
    cm.stop();
    return RL_OK;
}
