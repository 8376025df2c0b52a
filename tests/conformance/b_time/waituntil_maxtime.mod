MODULE MainModule
  ! Tests: WaitUntil with \MaxTime and no \TimeFlag raises ERR_WAIT_MAXTIME on timeout.
  PROC main()
    VAR num n := 1;
    WaitUntil n > 3 \MaxTime:=1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      TPWrite "ERR_WAIT_MAXTIME";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
