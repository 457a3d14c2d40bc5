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
    RinglocFuser(ArRobot *robot, FILE *log, double cycle) : myRobot(robot), myLog(log), myTask(this, &RinglocFuser::cycle)
    {
        myOffset = clock_offset();
        rl_fuse_config cfg;
        rl_fuse_defaults(&cfg);
        cfg.track = 0.33;            /* a Pioneer 3-DX's wheel base; the filter learns the rest */
        cfg.wheel_noise = 0.0005;
        cfg.time_sigma = 0.002;      /* ArTime counts milliseconds */
        /* 2.5 s of ARIA's 10 server information packets a second */
        myOk = rl_fuse_init(&myFuse, &cfg, myHist, rl_fuse_history_count(2.5, 10)) == RL_OK &&
               rl_fuse_cycle_init(&myCycle, cycle) == RL_OK;
        myLastRead = -1;
        myFused = 0;
        robot->addSensorInterpTask("ringloc fuse", 10, &myTask);
    }

    bool ok() const { return myOk; }

    /* the robot's thread, the robot locked: a new odometry pose */
    void cycle()
    {
        ArPose e = myRobot->getEncoderPose();
        double read = secs(myRobot->getLastOdometryTime()), t;
        rl_fuse_pose p;
        bool have;
        if (read == myLastRead)
            return; /* no new packet this cycle */
        myLastRead = read;
        t = rl_fuse_cycle_stamp(&myCycle, read);
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
            fprintf(myLog, "%.4f %.5f %.5f %.5f %.5f %.5f %.5f %.6f\n", t - myOffset, p.x, p.y, p.yaw, myRobot->getX() / 1000,
                    myRobot->getY() / 1000, ArMath::degToRad(myRobot->getTh()), sqrt(p.cov[0][0] + p.cov[1][1]));
    }

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
        myMutex.lock();
        if (rl_fuse_msg_add(&myFuse, &m, arrival, baud) != RL_OK) {
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

/* the robot stopped; the fused pose, ARIA's and the frames' fates logged */
static void report(ArRobot *robot, RinglocFuser *fuser)
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
                              "%lu restarts, %lu too old, %lu out of order, %lu clock resets, %lu untimed",
               fuser->fused(), s.applied, s.rejected, s.recoveries, s.too_old, s.out_of_order, s.clock_resets,
               s.untimed);
}

int main(int argc, char **argv)
{
    Aria::init();
    ArArgumentParser parser(&argc, argv);
    parser.loadDefaultArguments();
    ArRobot robot;
    ArRobotConnector connector(&parser, &robot);
    const char *port = "/dev/ttyUSB1", *logPath = NULL, *arrivalsPath = NULL;
    int baud = 115200;
    double drive = 0, vel = 0, rotVel = 0;
    int cycleMs = 100;
    if (!parser.checkParameterArgumentString("-ringlocPort", &port) ||
        !parser.checkParameterArgumentInteger("-ringlocBaud", &baud) ||
        !parser.checkParameterArgumentDouble("-drive", &drive) ||
        !parser.checkParameterArgumentDouble("-vel", &vel) ||
        !parser.checkParameterArgumentDouble("-rotVel", &rotVel) ||
        !parser.checkParameterArgumentString("-poseLog", &logPath) ||
        !parser.checkParameterArgumentString("-arrivalsLog", &arrivalsPath) ||
        !parser.checkParameterArgumentInteger("-odometryCycle", &cycleMs) || !Aria::parseArgs() ||
        !parser.checkHelpAndWarnUnparsed()) {
        ArLog::log(ArLog::Terse, "usage: ringloc-aria-fuse [ARIA's robot options] [-ringlocPort /dev/ttyUSB1] "
                                 "[-ringlocBaud 115200] [-drive SECONDS -vel MM/S -rotVel DEG/S] [-poseLog FILE] "
                                 "[-arrivalsLog FILE] [-odometryCycle MS (the robot's packet cycle, 100)]");
        Aria::logOptions();
        Aria::exit(2);
    }
    if (!connector.connectRobot()) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: could not connect to the robot");
        Aria::exit(1);
    }
    ArSerialConnection line;
    line.setPort(port);
    line.setBaud(baud);
    if (!line.openSimple()) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s: cannot open ringloc's serial line", port);
        Aria::exit(1);
    }
    ArRobotPacketReceiver rx(&line);
    /* the logs: temporaries beside their targets, renamed over them at the end */
    rl_outfile logFile, arrivalsFile;
    char err[1200];
    if (logPath && rl_outfile_open(&logFile, logPath, err, sizeof err) != RL_OK) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s", err);
        Aria::exit(1);
    }
    if (arrivalsPath && rl_outfile_open(&arrivalsFile, arrivalsPath, err, sizeof err) != RL_OK) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s", err);
        if (logPath)
            rl_outfile_abort(&logFile);
        Aria::exit(1);
    }
    FILE *log = logPath ? logFile.f : NULL, *arrivals = arrivalsPath ? arrivalsFile.f : NULL;
    RinglocFuser fuser(&robot, log, cycleMs / 1000.0);
    if (!fuser.ok()) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: -odometryCycle %d: not a cycle of 1 .. 10000 ms", cycleMs);
        Aria::exit(2);
    }
    robot.runAsync(true);
    robot.lock();
    robot.enableMotors();
    robot.setVel(vel);
    robot.setRotVel(rotVel);
    robot.unlock();
    ArTime start;
    while (robot.isRunning() && (drive <= 0 || start.secSince() < drive)) {
        ArRobotPacket *p = rx.receivePacket(200);
        if (p != NULL && p->getID() == RL_PACKET_POSE) {
            ArTime now;
            fuser.frame(p, secs(now), baud, arrivals);
        }
    }
    report(&robot, &fuser);
    robot.stopRunning();
    robot.waitForRunExit();
    int rc = 0; /* a log that cannot be written whole leaves the old file as it was */
    if (logPath && rl_outfile_commit(&logFile, err, sizeof err) != RL_OK) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s", err);
        rc = 1;
    }
    if (arrivalsPath && rl_outfile_commit(&arrivalsFile, err, sizeof err) != RL_OK) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s", err);
        rc = 1;
    }
    Aria::exit(rc);
    return 0;
}
