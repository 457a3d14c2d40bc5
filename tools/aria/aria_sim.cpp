/* aria_sim: see aria_sim.h. */
#include "aria_sim.h"
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

AriaSim::~AriaSim()
{
    if (myFd >= 0)
        close(myFd);
}

bool AriaSim::openStream(const char *path)
{
    /* a FIFO opened for writing without blocking fails (ENXIO) until its
     * reader is there */
    for (int i = 0; i < 100; i++) {
        myFd = open(path, O_WRONLY | O_NONBLOCK | O_CLOEXEC);
        if (myFd >= 0 || errno != ENXIO)
            break;
        ArUtil::sleep(100);
    }
    if (myFd < 0)
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s: cannot open the pose stream: %s", path,
                   errno == ENXIO ? "nobody reads it (start ringloc-render --path stream first)" : strerror(errno));
    return myFd >= 0;
}

bool AriaSim::truth(ArPose *p)
{
    *p = mySim.getSimTruePose();
    /* ArSimUtil starts at (0, 0, 0); AMRISim's SIMSTAT never reports it
     * exactly unless the robot is there: good enough to wait for a packet */
    return p->getX() != 0 || p->getY() != 0 || p->getTh() != 0;
}

void AriaSim::stream(double t, const ArPose &truth)
{
    if (myFd < 0)
        return;
    char line[96];
    int n = snprintf(line, sizeof line, "%lld %.3f %.3f %.6f\n", (long long)(t * 1e6 + 0.5), truth.getX() / 1000,
                     truth.getY() / 1000, ArMath::degToRad(truth.getTh()));
    /* a pipe takes writes of up to PIPE_BUF bytes whole or not at all */
    if (write(myFd, line, (size_t)n) == n)
        mySent++;
    else
        myDropped++;
}

bool AriaSim::push(const ArPose &d)
{
    ArPose p = mySim.getSimTruePose();
    return mySim.setSimTruePose(ArPose(p.getX() + d.getX(), p.getY() + d.getY(), p.getTh() + d.getTh()));
}
