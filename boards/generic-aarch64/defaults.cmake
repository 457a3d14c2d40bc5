# Any aarch64 Linux board: a USB webcam over V4L2, pose frames on a USB
# serial adapter.
set(RL_BOARD_CAMERA v4l2)
set(RL_BOARD_CAMERA_DEVICE /dev/video0)
set(RL_BOARD_SERIAL /dev/ttyUSB0)
set(RL_BOARD_BAUD 115200)
