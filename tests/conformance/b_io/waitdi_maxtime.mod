MODULE MainModule
  ! Tests: WaitDI with \MaxTime raises ERR_WAIT_MAXTIME when the input never reaches the value.
  VAR signaldi diStart;
  PROC main()
    AliasIO "di1", diStart;
    WaitDI diStart, 1 \MaxTime:=1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      TPWrite "ERR_WAIT_MAXTIME";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
