-- a Lua error whose message holds escape sequences and a newline
error("\27[31mboom\27[0m\nsecond line")
