-- A tableau file with a Lua syntax error (test fixture for vigen check).
return {
  name = "broken",
  s = 1,
  c = { "0" }
  A = { { "0" } },
}
