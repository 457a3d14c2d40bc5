# The desktop host build: native compiler, PNG files in, files or stdout out.
set(RL_BOARD_NAME host)
