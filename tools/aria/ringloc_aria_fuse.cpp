/* ringloc-aria-fuse: ARIA end to end. Connects to the robot (ArRobotConnector:
 * a Pioneer on a serial port, or -remoteHost/-remoteRobotTcpPort for
 * MobileSim or ringloc-standin), reads ringloc's pose frames on a second
 * serial port with ArRobotPacketReceiver, fuses them with the robot's
 * odometry through rl_fuse and keeps ArRobot's pose right with
 * moveTo(to, from) after every server information packet.
 *
 * Clocks: ARIA's ArTime is CLOCK_MONOTONIC. The odometry's time is the
 * packet's (getLastOdometryTime, less ArRobot's odometry delay); a frame is
 * stamped when ArRobotPacketReceiver hands it over in this thread, which
 * does nothing else, and its capture is that less its latency and its
 * bytes' time on the line (rl_fuse_frame_from_msg).
 *
 * The pose log (-poseLog): per packet "t x y yaw ariaX ariaY ariaYaw sigma"
 * (t: CLOCK_MONOTONIC s; m, rad; sigma: the fused position's, m).
 *
 *   ringloc-aria-fuse -remoteHost localhost -remoteRobotTcpPort 8101 \
 *       -ringlocPort /dev/ttyUSB1 -drive 20 -vel 500 -rotVel 20 -poseLog poses.txt */
#include <Aria/Aria.h>
#include <cstdio>
#include <ctime>
#include "rl_fuse.h"

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
    RinglocFuser(ArRobot *robot, FILE *log) : myRobot(robot), myLog(log), myTask(this, &RinglocFuser::cycle)
    {
        myOffset = clock_offset();
        rl_fuse_config cfg;
        rl_fuse_defaults(&cfg);
        cfg.track = 0.33;            /* a Pioneer 3-DX's wheel base; the filter learns the rest */
        cfg.wheel_noise = 0.0005;
        cfg.time_sigma = 0.002;      /* ArTime counts milliseconds */
        myOk = rl_fuse_init(&myFuse, &cfg) == RL_OK;
        myFused = 0;
        robot->addSensorInterpTask("ringloc fuse", 10, &myTask);
    }

    bool ok() const { return myOk; }

    /* the robot's thread, the robot locked: a new odometry pose */
    void cycle()
    {
        ArPose e = myRobot->getEncoderPose();
        double t = secs(myRobot->getLastOdometryTime());
        rl_fuse_pose p;
        bool have;
        myMutex.lock();
        have = rl_fuse_odometry(&myFuse, t, e.getX() / 1000, e.getY() / 1000, ArMath::degToRad(e.getTh())) == RL_OK &&
               rl_fuse_pose_at(&myFuse, t, &p) == RL_OK;
        myMutex.unlock();
        if (!have)
            return; /* no new packet this cycle, or no frame yet */
        /* from: where ARIA had the robot at that packet; to: where it was */
        myRobot->moveTo(ArPose(p.x * 1000, p.y * 1000, ArMath::radToDeg(p.yaw)), myRobot->getPose());
        myFused++;
        if (myLog)
            fprintf(myLog, "%.4f %.5f %.5f %.5f %.5f %.5f %.5f %.6f\n", t - myOffset, p.x, p.y, p.yaw, myRobot->getX() / 1000,
                    myRobot->getY() / 1000, ArMath::degToRad(myRobot->getTh()), sqrt(p.cov[0][0] + p.cov[1][1]));
    }

    /* the reader's thread: one ARCOS packet from ringloc's line */
    void frame(ArRobotPacket *packet, double arrival, int baud)
    {
        rl_decoder d;
        rl_msg m;
        rl_fuse_frame fr;
        const unsigned char *b = (const unsigned char *)packet->getBuf();
        bool got = false;
        rl_decoder_init(&d); /* ARIA checked the framing; rl_packet reads the fields */
        for (unsigned i = 0; i < packet->getLength(); i++)
            got = rl_decoder_push(&d, b[i], &m) || got;
        if (!got || m.type != RL_PACKET_POSE)
            return;
        rl_fuse_frame_from_msg(&m, arrival, baud, &fr);
        myMutex.lock();
        if (rl_fuse_frame_add(&myFuse, &fr) != RL_OK) {
            /* rejected or too old: counted in the stats */
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
    bool myOk;
    unsigned long myFused;
    double myOffset;
};

int main(int argc, char **argv)
{
    Aria::init();
    ArArgumentParser parser(&argc, argv);
    parser.loadDefaultArguments();
    ArRobot robot;
    ArRobotConnector connector(&parser, &robot);
    const char *port = "/dev/ttyUSB1", *logPath = NULL;
    int baud = 115200;
    double drive = 0, vel = 0, rotVel = 0;
    if (!parser.checkParameterArgumentString("-ringlocPort", &port) ||
        !parser.checkParameterArgumentInteger("-ringlocBaud", &baud) ||
        !parser.checkParameterArgumentDouble("-drive", &drive) ||
        !parser.checkParameterArgumentDouble("-vel", &vel) ||
        !parser.checkParameterArgumentDouble("-rotVel", &rotVel) ||
        !parser.checkParameterArgumentString("-poseLog", &logPath) || !Aria::parseArgs() ||
        !parser.checkHelpAndWarnUnparsed()) {
        ArLog::log(ArLog::Terse, "usage: ringloc-aria-fuse [ARIA's robot options] [-ringlocPort /dev/ttyUSB1] "
                                 "[-ringlocBaud 115200] [-drive SECONDS -vel MM/S -rotVel DEG/S] [-poseLog FILE]");
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
    FILE *log = logPath ? fopen(logPath, "w") : NULL;
    if (logPath && log == NULL) {
        ArLog::log(ArLog::Terse, "ringloc-aria-fuse: %s: cannot write", logPath);
        Aria::exit(1);
    }
    RinglocFuser fuser(&robot, log);
    if (!fuser.ok())
        Aria::exit(1);
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
            fuser.frame(p, secs(now), baud);
        }
    }
    robot.lock();
    robot.stop();
    ArPose aria = robot.getPose();
    double t = secs(robot.getLastOdometryTime());
    robot.unlock();
    rl_fuse_stats s = fuser.stats();
    rl_fuse_pose p;
    if (fuser.pose(t, &p))
        ArLog::log(ArLog::Normal, "ringloc-aria-fuse: fused pose (%.4f m, %.4f m, %.4f rad), sigma %.2f mm; "
                                  "ARIA's pose (%.1f mm, %.1f mm, %.2f deg); odometry scale %.4f, turn %.4f",
                   p.x, p.y, p.yaw, 1000 * sqrt(p.cov[0][0] + p.cov[1][1]), aria.getX(), aria.getY(),
                   aria.getTh(), p.scale, p.turn);
    ArLog::log(ArLog::Normal, "ringloc-aria-fuse: %lu packets fused; frames: %lu applied, %lu rejected, "
                              "%lu restarts, %lu too old, %lu out of order",
               fuser.fused(), s.applied, s.rejected, s.recoveries, s.too_old, s.out_of_order);
    robot.stopRunning();
    robot.waitForRunExit();
    if (log)
        fclose(log);
    Aria::exit(0);
    return 0;
}
