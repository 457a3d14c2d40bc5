/* aria_route: see aria_route.h. */
#include "aria_route.h"
#include <cstdio>
#include <cstring>

AriaRoute::AriaRoute(ArRobot *robot, double closeDist, double speed)
    : myRobot(robot), myGoto("ringloc route", ArPose(0, 0, 0), closeDist, speed), myTask(this, &AriaRoute::step),
      myCur(0), myTaken(0)
{
}

bool AriaRoute::load(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s: cannot read the route", path);
        return false;
    }
    char line[256];
    int no = 0;
    bool ok = true;
    while (ok && fgets(line, sizeof line, f)) {
        double x, y;
        char extra;
        no++;
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        int n = sscanf(line, "%lf %lf %c", &x, &y, &extra);
        if (n == 2)
            myGoals.push_back(ArPose(x * 1000, y * 1000));
        else if (n != EOF) {
            ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s:%d: not 'X Y' (metres)", path, no);
            ok = false;
        }
    }
    fclose(f);
    if (ok && myGoals.empty()) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s: no waypoint", path);
        ok = false;
    }
    return ok;
}

void AriaRoute::start()
{
    myCur = 0;
    myRobot->clearDirectMotion();
    myRobot->addAction(&myGoto, 50);
    myGoto.setGoal(myGoals[0]);
    myRobot->addUserTask("ringloc route", 50, &myTask);
}

void AriaRoute::step()
{
    ArScopedLock l(myMutex);
    if (myCur >= myGoals.size() || !myGoto.haveAchievedGoal())
        return;
    Reached r = {myCur, (double)myRobot->getLastOdometryTime().getSecLL() +
                            (double)myRobot->getLastOdometryTime().getMSecLL() / 1000.0,
                 myRobot->getPose()};
    myReached.push_back(r);
    myCur++;
    if (myCur < myGoals.size())
        myGoto.setGoal(myGoals[myCur]);
}

bool AriaRoute::takeReached(Reached *r)
{
    ArScopedLock l(myMutex);
    if (myTaken >= myReached.size())
        return false;
    *r = myReached[myTaken++];
    return true;
}

bool AriaRoute::done()
{
    ArScopedLock l(myMutex);
    return myCur >= myGoals.size() && myTaken >= myReached.size();
}

size_t AriaRoute::current()
{
    ArScopedLock l(myMutex);
    return myCur;
}
