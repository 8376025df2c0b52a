MODULE MainModule
  ! Tests: WaitDI with \TimeFlag sets the flag FALSE when the input has the value in time.
  VAR signaldi diStart;
  PROC main()
    VAR bool late := TRUE;
    AliasIO "di1", diStart;
    WaitDI diStart, 1 \MaxTime:=0.5 \TimeFlag:=late;
    TPWrite "timed out=" \Bool:=late;
  ENDPROC
ENDMODULE
