/* aria_sim: what ringloc-aria-fuse takes from a simulator (AMRISim,
 * MobileSim) and gives it: the simulated robot's true pose, asked for with
 * SIM_STAT and kept by ARIA's ArSimUtil (SIMSTAT packets, about 10 a
 * second, whole millimetres and degrees), streamed as "T_US X Y YAW" lines
 * (CLOCK_MONOTONIC microseconds, m, m, rad: ringloc-render --path stream's
 * input) into a pipe; and the push: the robot set aside with SIM_SET_POSE,
 * its odometry untouched.
 *
 *   AriaSim sim(&robot);                 // before connecting or after
 *   if (!sim.openStream("poses.fifo")) ...
 *   // each SIP, robot locked, t its odometry's time on CLOCK_MONOTONIC:
 *   ArPose truth = sim.truth(); sim.stream(t, truth);
 *   sim.push(ArPose(300, 0, 10));        // 300 mm along x, 10 degrees more
 *
 * The stream's writes never block the robot's thread: a pose the reader
 * has no room for is dropped and counted (dropped()). */
#ifndef ARIA_SIM_H
#define ARIA_SIM_H

#include <Aria/Aria.h>
#include <Aria/ArSimUtil.h>

class AriaSim
{
public:
    explicit AriaSim(ArRobot *robot) : mySim(robot), myFd(-1), myDropped(0), mySent(0) {}
    ~AriaSim();

    /* the pipe's writing end, opened without blocking; waits up to 10 s for
     * its reader (the renderer). false, with one line logged, if it fails */
    bool openStream(const char *path);

    /* the latest true pose (mm, mm, degrees); false before the first SIMSTAT */
    bool truth(ArPose *p);

    /* one "T_US X Y YAW" line for the pose at t (CLOCK_MONOTONIC s) */
    void stream(double t, const ArPose &truth);

    /* the true pose moved by d (mm, mm, degrees; in the world's frame) */
    bool push(const ArPose &d);

    unsigned long dropped() const { return myDropped; }
    unsigned long sent() const { return mySent; }

private:
    ArSimUtil mySim;
    int myFd;
    unsigned long myDropped, mySent;
};

#endif
