# The desktop host: the native compiler (nothing to set).
