/* ringloc-aria-fuse: ARIA end to end. Connects to the robot (ArRobotConnector:
 * a Pioneer on a serial port, or -remoteHost/-remoteRobotTcpPort for
 * MobileSim or ringloc-standin), reads ringloc's pose frames on a second
 * serial port with ArRobotPacketReceiver, fuses them with the robot's
 * odometry through rl_fuse and keeps ArRobot's pose right with
 * moveTo(to, from) after every server information packet.
 *
 * Clocks: ARIA's ArTime is CLOCK_MONOTONIC. The odometry's time is the
 * packet's (getLastOdometryTime, less ArRobot's odometry delay) moved to
 * the robot's packet cycle (rl_fuse_cycle, -odometryCycle MS, ARCOS's 100
 * by default): a loaded machine that reads a packet 60 ms late would
 * otherwise put the robot 60 mm behind at 1 m/s; a frame is
 * stamped on that clock when ArRobotPacketReceiver hands it over, and
 * rl_fuse_msg_add finds its capture from the camera board's time_ms and
 * those arrival stamps (a delay on the way does not matter).
 *
 * The pose log (-poseLog): per packet "t x y yaw ariaX ariaY ariaYaw sigma"
 * (t: CLOCK_MONOTONIC s; m, rad; sigma: the fused position's, m). The
 * arrivals (-arrivalsLog): per frame "seq arrival_seconds" on ArTime's
 * clock, the odometry's, for `ringloc fuse --arrivals`. Both are written
 * whole or not at all (rl_outfile: a temporary renamed over the target).
 *
 * `make sim` (docs/sim.md) adds: a route of waypoints driven with
 * ArActionGoto on the fused pose (-route, aria_route.cpp); with a simulator
 * (AMRISim), its true pose at each packet ending the pose log's lines and
 * streamed to ringloc-render (-simPoses, aria_sim.cpp), the frames cut for
 * a while (-cutAt, -cutFor) and the robot pushed aside (-pushAt, -push).
 *
 *   ringloc-aria-fuse -remoteHost localhost -remoteRobotTcpPort 8101 \
 *       -ringlocPort /dev/ttyUSB1 -drive 20 -vel 500 -rotVel 20 -poseLog poses.txt \
 *       -arrivalsLog arrivals.txt
 *
 * Built from the ringloc-fuse package's examples folder (rl_outfile.c and
 * .h beside this file):
 *   cc -c rl_outfile.c $(pkg-config --cflags ringloc-fuse)
 *   c++ -I. ringloc_aria_fuse.cpp rl_outfile.o $(pkg-config --cflags --libs ringloc-fuse) -lAria \
 *       -lpthread -ldl -o ringloc-aria-fuse */
#include <Aria/Aria.h>
#include <cstdio>
#include <ctime>
#include "aria_route.h"
#include "aria_sim.h"
#include "rl_fuse.h"
extern "C" {
#include "rl_outfile.h"
}

static double secs(const ArTime &t)
{
    return (double)t.getSecLL() + (double)t.getMSecLL() / 1000.0;
}

/* ArTime's seconds less CLOCK_MONOTONIC's (AriaCoda counts from another
 * origin): the pose log is on CLOCK_MONOTONIC, as ringloc-standin's truth */
static double clock_offset()
{
    struct timespec ts;
    ArTime now;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return secs(now) - ((double)ts.tv_sec + ts.tv_nsec * 1e-9);
}

/* The filter between the robot's thread (odometry, after each packet) and
 * the frames' reader (this program's main thread). */
class RinglocFuser
{
public:
    RinglocFuser(ArRobot *robot, FILE *log, AriaSim *sim, double floorXY, double floorYaw, double cycle)
        : myRobot(robot), myLog(log), mySim(sim), myShared(false), myTask(this, &RinglocFuser::cycle)
    {
        myOffset = clock_offset();
        rl_fuse_config cfg;
        rl_fuse_defaults(&cfg);
        cfg.track = 0.33;            /* a Pioneer 3-DX's wheel base; the filter learns the rest */
        cfg.wheel_noise = 0.0005;
        cfg.time_sigma = 0.002;      /* ArTime counts milliseconds */
        if (floorXY > 0)             /* what the frames' sigmas leave out (the robot rocking, */
            cfg.floor_xy = floorXY;  /* a simulator's truth in whole mm and degrees) */
        if (floorYaw > 0)
            cfg.floor_yaw = floorYaw;
        /* 2.5 s of ARIA's 10 server information packets a second */
        myOk = rl_fuse_init(&myFuse, &cfg, myHist, rl_fuse_history_count(2.5, 10)) == RL_OK &&
               rl_fuse_cycle_init(&myCycle, cycle) == RL_OK;
        myLastRead = -1;
        myFused = 0;
        myWaypoint = -1;
        robot->addSensorInterpTask("ringloc fuse", 10, &myTask);
    }

    bool ok() const { return myOk; }

    /* the robot's thread, the robot locked: a new odometry pose */
    void cycle()
    {
        ArPose e = myRobot->getEncoderPose(), truth;
        double read = secs(myRobot->getLastOdometryTime()), t;
        rl_fuse_pose p;
        bool have, simulated;
        if (read == myLastRead)
            return; /* no new packet this cycle */
        myLastRead = read;
        t = rl_fuse_cycle_stamp(&myCycle, read);
        simulated = mySim && mySim->truth(&truth);
        if (simulated) /* the truth at this packet: the renderer draws it */
            mySim->stream(t - myOffset, truth);
        myMutex.lock();
        have = rl_fuse_odometry(&myFuse, t, e.getX() / 1000, e.getY() / 1000, ArMath::degToRad(e.getTh())) == RL_OK &&
               rl_fuse_pose_at(&myFuse, t, &p) == RL_OK;
        myMutex.unlock();
        if (!have)
            return; /* no frame yet */
        /* from: where ARIA had the robot at that packet; to: where it was */
        myRobot->moveTo(ArPose(p.x * 1000, p.y * 1000, ArMath::radToDeg(p.yaw)), myRobot->getPose());
        myFused++;
        if (myLog)
            fprintf(myLog, "%.4f %.5f %.5f %.5f %.5f %.5f %.5f %.6f", t - myOffset, p.x, p.y, p.yaw,
                    myRobot->getX() / 1000, myRobot->getY() / 1000, ArMath::degToRad(myRobot->getTh()),
                    sqrt(p.cov[0][0] + p.cov[1][1]));
        if (myLog && simulated)
            fprintf(myLog, " %.3f %.3f %.6f %d\n", truth.getX() / 1000, truth.getY() / 1000,
                    ArMath::degToRad(truth.getTh()), myWaypoint);
        else if (myLog)
            fputc('\n', myLog);
    }

    /* the camera board's time_ms is this machine's CLOCK_MONOTONIC (ringloc-fw
     * beside this program, as in make sim): each capture time is known, the
     * board's clock is not learned from the arrivals */
    void setSharedClock(bool shared) { myShared = shared; }

    /* the waypoint being driven to, for the log (-1: none) */
    void setWaypoint(int i) { myWaypoint = i; }

    /* the reader's thread: one ARCOS packet from ringloc's line, arrived
     * at `arrival` (ArTime s); its sequence and arrival into `arrivals` */
    void frame(ArRobotPacket *packet, double arrival, int baud, FILE *arrivals)
    {
        rl_decoder d;
        rl_msg m;
        const unsigned char *b = (const unsigned char *)packet->getBuf();
        bool got = false;
        rl_decoder_init(&d); /* ARIA checked the framing; rl_packet reads the fields */
        for (unsigned i = 0; i < packet->getLength(); i++)
            got = rl_decoder_push(&d, b[i], &m) || got;
        if (!got || m.type != RL_PACKET_POSE)
            return;
        if (arrivals)
            fprintf(arrivals, "%u %.6f\n", (unsigned)m.seq, arrival);
        rl_fuse_frame fr;
        if (myShared) {
            rl_fuse_frame_from_msg(&m, 0, 0, &fr);
            fr.t = m.time_ms / 1000.0 + myOffset; /* on ArTime's clock */
            fr.st = 0.0005;                        /* time_ms counts milliseconds */
        }
        myMutex.lock();
        if ((myShared ? rl_fuse_frame_add(&myFuse, &fr) : rl_fuse_msg_add(&myFuse, &m, arrival, baud)) != RL_OK) {
            rl_fuse_event ev; /* rejected, too old, waiting for the board's clock: */
            rl_fuse_last_event(&myFuse, &ev);  /* counted in the stats */
            if (ev.fate == RL_FUSE_REJECTED)
                ArLog::log(ArLog::Verbose, "ringloc-aria-fuse: frame %u rejected, distance^2 %.1f", ev.seq, ev.d2);
        }
        myMutex.unlock();
    }

    rl_fuse_stats stats()
    {
        myMutex.lock();
        rl_fuse_stats s = myFuse.stats;
        myMutex.unlock();
        return s;
    }

    bool pose(double t, rl_fuse_pose *p)
    {
        myMutex.lock();
        rl_err e = rl_fuse_pose_at(&myFuse, t, p);
        myMutex.unlock();
        if (e != RL_OK)
            ArLog::log(ArLog::Normal, "ringloc-aria-fuse: no fused pose at %.3f s: %s", t, rl_strerror(e));
        return e == RL_OK;
    }

    unsigned long fused() const { return myFused; }

private:
    ArRobot *myRobot;
    FILE *myLog;
    AriaSim *mySim;
    bool myShared;
    int myWaypoint;
    ArFunctorC<RinglocFuser> myTask;
    ArMutex myMutex;
    rl_fuse myFuse;
    rl_fuse_entry myHist[64];
    rl_fuse_cycle myCycle;     /* the odometry's packet cycle */
    double myLastRead;
    bool myOk;
    unsigned long myFused;
    double myOffset;
};

/* -push DX,DY,DTH (mm, mm, degrees) */
static bool parsePush(const char *s, ArPose *d)
{
    double x, y, th;
    char extra;
    if (!s)
        return true;
    if (sscanf(s, "%lf,%lf,%lf %c", &x, &y, &th, &extra) != 3) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: -push %s: not DX,DY,DTH (mm, mm, degrees)", s);
        return false;
    }
    *d = ArPose(x, y, th);
    return true;
}

/* a waypoint reached: "i goal_x goal_y t ariaX ariaY trueX trueY" (m, s) */
static void logReached(FILE *f, const AriaRoute &route, size_t i, double t, const ArPose &aria, AriaSim *sim)
{
    ArPose truth, g = route.goal(i);
    bool have = sim && sim->truth(&truth);
    ArLog::log(ArLog::Normal, "ringloc-aria-fuse: waypoint %zu (%.3f m, %.3f m) reached: ARIA's pose %.1f mm off%s",
               i, g.getX() / 1000, g.getY() / 1000, aria.findDistanceTo(g), have ? ", the truth " : "");
    if (have)
        ArLog::log(ArLog::Normal, "ringloc-aria-fuse:   the truth %.0f mm off (whole mm)", truth.findDistanceTo(g));
    if (f)
        fprintf(f, "%zu %.4f %.4f %.4f %.5f %.5f %.3f %.3f\n", i, g.getX() / 1000, g.getY() / 1000, t,
                aria.getX() / 1000, aria.getY() / 1000, have ? truth.getX() / 1000 : NAN,
                have ? truth.getY() / 1000 : NAN);
}

/* the robot stopped; the fused pose, ARIA's, the frames' fates, the route's
 * waypoints and the true poses streamed logged */
static void report(ArRobot *robot, RinglocFuser *fuser, unsigned long cut, AriaRoute *route, AriaSim *streamed)
{
    robot->lock();
    robot->stop();
    ArPose aria = robot->getPose();
    double t = secs(robot->getLastOdometryTime());
    robot->unlock();
    rl_fuse_stats s = fuser->stats();
    rl_fuse_pose p;
    if (fuser->pose(t, &p))
        ArLog::log(ArLog::Normal, "ringloc-aria-fuse: fused pose (%.4f m, %.4f m, %.4f rad), sigma %.2f mm; "
                                  "ARIA's pose (%.1f mm, %.1f mm, %.2f deg); odometry scale %.4f, turn %.4f",
                   p.x, p.y, p.yaw, 1000 * sqrt(p.cov[0][0] + p.cov[1][1]), aria.getX(), aria.getY(),
                   aria.getTh(), p.scale, p.turn);
    ArLog::log(ArLog::Normal, "ringloc-aria-fuse: %lu packets fused; frames: %lu applied, %lu rejected, "
                              "%lu restarts, %lu too old, %lu out of order, %lu clock resets, %lu untimed, %lu cut",
               fuser->fused(), s.applied, s.rejected, s.recoveries, s.too_old, s.out_of_order, s.clock_resets,
               s.untimed, cut);
    if (route)
        ArLog::log(ArLog::Normal, "ringloc-aria-fuse: route: %zu of %zu waypoints reached", route->current(),
                   route->count());
    if (streamed)
        ArLog::log(ArLog::Normal, "ringloc-aria-fuse: true poses streamed: %lu, dropped (the reader busy): %lu",
                   streamed->sent(), streamed->dropped());
}

/* the command line's options, ARIA's own left to ARIA */
struct Options {
    const char *port = "/dev/ttyUSB1", *logPath = NULL, *arrivalsPath = NULL, *simPoses = NULL, *routePath = NULL,
               *routeLogPath = NULL, *pushArg = NULL;
    int baud = 115200, cycleMs = 100;
    double drive = 0, vel = 0, rotVel = 0, frameFloor = 0, frameFloorYaw = 0;
    double closeDist = 20, routeVel = 400, cutAt = -1, cutFor = 3, pushAt = -1;
    bool sharedClock = false;
    ArPose pushBy;
};

/* the options into *o; false (the usage logged) when one is wrong */
static bool parseOptions(ArArgumentParser &parser, Options *o)
{
    if (!parser.checkParameterArgumentString("-ringlocPort", &o->port) ||
        !parser.checkParameterArgumentInteger("-ringlocBaud", &o->baud) ||
        !parser.checkParameterArgumentDouble("-drive", &o->drive) ||
        !parser.checkParameterArgumentDouble("-vel", &o->vel) ||
        !parser.checkParameterArgumentDouble("-rotVel", &o->rotVel) ||
        !parser.checkParameterArgumentString("-poseLog", &o->logPath) ||
        !parser.checkParameterArgumentString("-arrivalsLog", &o->arrivalsPath) ||
        !parser.checkParameterArgumentInteger("-odometryCycle", &o->cycleMs) ||
        !parser.checkParameterArgumentDouble("-frameFloor", &o->frameFloor) ||
        !parser.checkParameterArgumentDouble("-frameFloorYaw", &o->frameFloorYaw) ||
        !parser.checkParameterArgumentString("-simPoses", &o->simPoses) ||
        !parser.checkParameterArgumentBool("-sharedClock", &o->sharedClock) ||
        !parser.checkParameterArgumentString("-route", &o->routePath) ||
        !parser.checkParameterArgumentString("-routeLog", &o->routeLogPath) ||
        !parser.checkParameterArgumentDouble("-closeDist", &o->closeDist) ||
        !parser.checkParameterArgumentDouble("-routeVel", &o->routeVel) ||
        !parser.checkParameterArgumentDouble("-cutAt", &o->cutAt) ||
        !parser.checkParameterArgumentDouble("-cutFor", &o->cutFor) ||
        !parser.checkParameterArgumentDouble("-pushAt", &o->pushAt) ||
        !parser.checkParameterArgumentString("-push", &o->pushArg) || !parsePush(o->pushArg, &o->pushBy) ||
        !Aria::parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
        ArLog::log(ArLog::Terse,
                   "usage: ringloc-aria-fuse [ARIA's robot options] [-ringlocPort /dev/ttyUSB1] [-ringlocBaud 115200]\n"
                   "         [-drive SECONDS -vel MM/S -rotVel DEG/S] [-poseLog FILE] [-arrivalsLog FILE]\n"
                   "         [-odometryCycle MS] [-frameFloor MM] [-frameFloorYaw DEG]\n"
                   "         [-route FILE [-routeLog FILE] [-closeDist 20] [-routeVel 400]]\n"
                   "         [-simPoses FIFO] [-cutAt S [-cutFor 3]] [-pushAt S -push DX,DY,DTH]\n"
                   "         [-sharedClock true]\n"
                   "  -odometryCycle MS  the robot's packet cycle (100): each packet's read time moved to it\n"
                   "                  (rl_fuse_cycle: a loaded machine reads some packets late)\n"
                   "  -frameFloor MM  added in quadrature to every frame's position sigma (rl_fuse's\n"
                   "                  floor_xy, default 0.5): what the frames' own sigmas leave out\n"
                   "  -frameFloorYaw DEG  the same for the heading (floor_yaw, default 0.03)\n"
                   "  -route FILE     drive to each waypoint ('X Y' a line, m) with ArActionGoto on the\n"
                   "                  fused pose (close enough: -closeDist mm; at most -routeVel mm/s), once\n"
                   "                  ten frames are applied; -drive is then the time limit\n"
                   "  -routeLog FILE  per waypoint reached: 'i goal_x goal_y t ariaX ariaY trueX trueY'\n"
                   "  -simPoses FIFO  a simulator's (AMRISim's) true pose at each packet (SIM_STAT) as\n"
                   "                  'T_US X Y YAW' lines for ringloc-render --path stream; each -poseLog\n"
                   "                  line then ends with 'trueX trueY trueYaw waypoint' (whole mm, degrees)\n"
                   "  -cutAt S        ringloc's frames dropped from S s after the route's start, -cutFor s\n"
                   "  -pushAt S       the simulated robot set aside by -push mm,mm,degrees at S s (SIM_SET_POSE)\n"
                   "  -sharedClock true  the frames' time_ms is this machine's CLOCK_MONOTONIC (ringloc-fw\n"
                   "                  on it): capture times taken as they are, not learned from arrivals");
        Aria::logOptions();
        return false;
    }
    return true;
}

/* the logs: temporaries beside their targets, renamed over them at the end
 * (a log that cannot be written whole leaves the old file as it was) */
static bool openLogs(const char *const paths[3], rl_outfile files[3], FILE *fs[3])
{
    char err[1200];
    for (int i = 0; i < 3; i++) {
        fs[i] = NULL;
        if (paths[i] && rl_outfile_open(&files[i], paths[i], err, sizeof err) != RL_OK) {
            ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s", err);
            while (i-- > 0)
                if (paths[i])
                    rl_outfile_abort(&files[i]);
            return false;
        }
        fs[i] = paths[i] ? files[i].f : NULL;
    }
    return true;
}

int main(int argc, char **argv)
{
    Aria::init();
    ArArgumentParser parser(&argc, argv);
    parser.loadDefaultArguments();
    ArRobot robot;
    ArRobotConnector connector(&parser, &robot);
    Options o;
    if (!parseOptions(parser, &o))
        Aria::exit(2);
    AriaRoute route(&robot, o.closeDist, o.routeVel);
    if (o.routePath && !route.load(o.routePath))
        Aria::exit(1);
    /* a simulator's truth asked for only where it is wanted (a Pioneer ignores SIM_STAT) */
    AriaSim *sim = o.simPoses || o.pushAt >= 0 ? new AriaSim(&robot) : NULL;
    if (!connector.connectRobot()) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: could not connect to the robot");
        Aria::exit(1);
    }
    if (o.simPoses && !sim->openStream(o.simPoses))
        Aria::exit(1);
    ArSerialConnection line;
    line.setPort(o.port);
    line.setBaud(o.baud);
    if (!line.openSimple()) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s: cannot open ringloc's serial line", o.port);
        Aria::exit(1);
    }
    ArRobotPacketReceiver rx(&line);
    const char *paths[3] = {o.logPath, o.arrivalsPath, o.routeLogPath};
    rl_outfile files[3];
    FILE *fs[3];
    char err[1200];
    if (!openLogs(paths, files, fs))
        Aria::exit(1);
    FILE *log = fs[0], *arrivals = fs[1], *routeLog = fs[2];
    RinglocFuser fuser(&robot, log, sim, o.frameFloor / 1000, ArMath::degToRad(o.frameFloorYaw), o.cycleMs / 1000.0);
    if (!fuser.ok()) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: -odometryCycle %d: not a cycle of 1 .. 10000 ms", o.cycleMs);
        Aria::exit(2);
    }
    fuser.setSharedClock(o.sharedClock);
    robot.runAsync(true);
    robot.lock();
    robot.enableMotors();
    if (!o.routePath) {
        robot.setVel(o.vel);
        robot.setRotVel(o.rotVel);
    }
    robot.unlock();
    ArTime start, routeStart;
    bool driving = !o.routePath, pushed = false;
    unsigned long cut = 0;
    while (robot.isRunning() && (o.drive <= 0 || start.secSince() < o.drive) && !(o.routePath && route.done())) {
        ArRobotPacket *p = rx.receivePacket(200);
        double since = driving ? routeStart.mSecSince() / 1000.0 : -1;
        if (p != NULL && p->getID() == RL_PACKET_POSE) {
            ArTime now;
            if (o.cutAt >= 0 && since >= o.cutAt && since < o.cutAt + o.cutFor)
                cut++; /* the cable cut: the frame never arrives */
            else
                fuser.frame(p, secs(now), o.baud, arrivals);
        }
        if (!driving && fuser.stats().applied >= 10) {
            robot.lock();
            route.start();
            fuser.setWaypoint(0);
            robot.unlock();
            routeStart.setToNow();
            driving = true;
            ArLog::log(ArLog::Normal, "ringloc-aria-fuse: the route's %zu waypoints, on the fused pose", route.count());
        }
        AriaRoute::Reached reached; /* the route steps in the robot's thread: no wait for its lock here */
        while (o.routePath && driving && route.takeReached(&reached)) {
            logReached(routeLog, route, reached.index, reached.t - clock_offset(), reached.pose, sim);
            fuser.setWaypoint(route.current() < route.count() ? (int)route.current() : -1);
        }
        if (sim && o.pushAt >= 0 && !pushed && since >= o.pushAt) {
            pushed = true;
            ArLog::log(ArLog::Normal, "ringloc-aria-fuse: pushing the robot by (%.0f mm, %.0f mm, %.0f deg)%s",
                       o.pushBy.getX(), o.pushBy.getY(), o.pushBy.getTh(), sim->push(o.pushBy) ? "" : ": failed");
        }
    }
    report(&robot, &fuser, cut, o.routePath ? &route : NULL, o.simPoses ? sim : NULL);
    robot.stopRunning();
    robot.waitForRunExit();
    delete sim;
    int rc = o.routePath && !route.done() ? 3 : 0; /* a log that cannot be written whole leaves the old file as it was */
    for (int i = 0; i < 3; i++)
        if (paths[i] && rl_outfile_commit(&files[i], err, sizeof err) != RL_OK) {
            ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s", err);
            rc = 1;
        }
    Aria::exit(rc);
    return 0;
}
