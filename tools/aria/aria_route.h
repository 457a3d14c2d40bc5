/* aria_route: a route of waypoints driven with ARIA's ArActionGoto on the
 * robot's pose as ARIA has it (ringloc-aria-fuse keeps it fused). A route
 * file holds one waypoint a line, "X Y" in metres in the map's frame ('#'
 * starts a comment); the robot goes to each in turn and stops there.
 *
 *   AriaRoute route(&robot, 20, 400);   // close enough at 20 mm, at most 400 mm/s
 *   if (!route.load("route.txt")) ...    // one line logged naming file and line
 *   route.start();                       // robot locked: goto, and a task that steps the route
 *   AriaRoute::Reached r;
 *   while (!route.done())
 *       if (route.takeReached(&r)) use(r.index, r.t, r.pose); // the robot not locked
 *
 * The route is stepped in the robot's thread (a user task), so that the
 * caller's thread never waits for the robot's lock (a reader that stamps
 * arrivals must not). */
#ifndef ARIA_ROUTE_H
#define ARIA_ROUTE_H

#include <Aria/Aria.h>
#include <vector>

class AriaRoute
{
public:
    AriaRoute(ArRobot *robot, double closeDist, double speed);
    bool load(const char *path);
    size_t count() const { return myGoals.size(); }
    void start();

    /* a waypoint reached: its index, the odometry's time then (ArTime s)
     * and ARIA's pose */
    struct Reached {
        size_t index;
        double t;
        ArPose pose;
    };
    /* the oldest waypoint reached not yet taken; false if none */
    bool takeReached(Reached *r);
    bool done();
    /* the waypoint being driven to (count() when done) */
    size_t current();
    ArPose goal(size_t i) const { return myGoals[i]; }

private:
    void step(); /* the robot's thread, robot locked */
    ArRobot *myRobot;
    ArActionGoto myGoto;
    ArFunctorC<AriaRoute> myTask;
    std::vector<ArPose> myGoals;
    std::vector<Reached> myReached;
    size_t myCur, myTaken;
    ArMutex myMutex;
};

#endif
