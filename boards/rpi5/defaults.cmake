# Raspberry Pi 5 (Raspberry Pi OS, aarch64): the Pi camera through
# libcamera, pose frames on the GPIO UART.
set(RL_BOARD_CAMERA libcamera)
set(RL_BOARD_CAMERA_DEVICE 0)
set(RL_BOARD_SERIAL /dev/serial0)
set(RL_BOARD_BAUD 115200)
