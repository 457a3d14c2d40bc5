/* aria_route: a route of waypoints driven with ARIA's ArActionGoto on the
 * robot's pose as ARIA has it (ringloc-aria-fuse keeps it fused). A route
 * file holds one waypoint a line, "X Y" in metres in the map's frame ('#'
 * starts a comment); the robot goes to each in turn and stops there.
 *
 *   AriaRoute route(&robot, 20, 400);   // close enough at 20 mm, at most 400 mm/s
 *   if (!route.load("route.txt")) ...    // one line logged naming file and line
 *   route.start();                       // robot locked
 *   while (!route.done())
 *       if (route.step()) use(route.reached()); // robot locked: the waypoint just reached */
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
    /* robot locked: true when the current waypoint has just been reached
     * (the next one is set); reached() is its index */
    bool step();
    size_t reached() const { return myCur - 1; }
    bool done() const { return myCur >= myGoals.size(); }
    /* the waypoint being driven to (the last one when done) */
    size_t current() const { return myCur; }
    ArPose goal(size_t i) const { return myGoals[i]; }

private:
    ArRobot *myRobot;
    ArActionGoto myGoto;
    std::vector<ArPose> myGoals;
    size_t myCur;
};

#endif
