MODULE MainModule
  ! Tests: InvertDO flips a digital output between 0 and 1.
  VAR signaldo doLamp;
  PROC main()
    AliasIO "DO1", doLamp;
    InvertDO doLamp;
    TPWrite "first=" \Num:=DOutput(doLamp);
    InvertDO doLamp;
    TPWrite "second=" \Num:=DOutput(doLamp);
    InvertDO doLamp;
    TPWrite "third=" \Num:=DOutput(doLamp);
  ENDPROC
ENDMODULE
