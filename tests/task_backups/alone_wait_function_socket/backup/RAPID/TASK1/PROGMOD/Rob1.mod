MODULE Rob1
  ! Written for the test (issue 28): robot 2 (not loaded) sets start_flag; robot 1 asks a
  ! function, then reads a reply with no \Time and no handler: a silent peer stops the
  ! task with ERR_SOCK_TIMEOUT, a true defect.
  PERS bool start_flag := FALSE;
  VAR socketdev peer;
  VAR string reply := "";

  FUNC bool Started()
    RETURN start_flag;
  ENDFUNC

  PROC main()
    WaitUntil Started();
    SocketCreate peer;
    SocketConnect peer, "192.168.125.5", 3000 \Time:=WAIT_MAX;
    SocketReceive peer \Str:=reply;
    SocketClose peer;
  ENDPROC
ENDMODULE
