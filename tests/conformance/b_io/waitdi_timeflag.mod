MODULE MainModule
  ! Tests: WaitDI with \MaxTime and \TimeFlag sets the flag TRUE on timeout and continues.
  VAR signaldi diStart;
  PROC main()
    VAR bool late;
    AliasIO "di1", diStart;
    WaitDI diStart, 1 \MaxTime:=0.5 \TimeFlag:=late;
    TPWrite "timed out=" \Bool:=late;
  ENDPROC
ENDMODULE
