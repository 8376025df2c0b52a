MODULE Client
  ! Written for the test (issue 28): command is written only by a client outside the
  ! loaded code, and this task waits for it; the wait stores the value it took
  ! (load.waited_data), so it writes command as far as the other task is concerned.
  PERS string command := "";
  PROC main()
    WaitUntil command <> "";             ! SHARED
  ENDPROC
ENDMODULE
