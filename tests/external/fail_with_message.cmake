# Fails a test with MESSAGE (cmake -DMESSAGE=... -P fail_with_message.cmake):
# the external tests report a missing tool instead of skipping.
message(FATAL_ERROR "${MESSAGE}")
