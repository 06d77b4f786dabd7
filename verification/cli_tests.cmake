# Command-line behaviour: bad input is refused with one clear line and a non-zero exit.
