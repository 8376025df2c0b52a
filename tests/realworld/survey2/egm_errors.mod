MODULE EgmGuard
  ! errnum names beyond the basic set, as an EGM or RMQ client handles them
  VAR num nTimeouts := 0;
  PROC main()
    Guarded ERR_UDPUC_COMM;
    Guarded ERR_RMQ_TIMEOUT;
    TPWrite "timeouts " \Num:=nTimeouts;
  ENDPROC
  PROC Guarded(errnum code)
    RAISE code;
  ERROR
    TEST ERRNO
    CASE ERR_UDPUC_COMM, ERR_RMQ_TIMEOUT:
      Incr nTimeouts;
      RETURN;
    ENDTEST
  ENDPROC
ENDMODULE
