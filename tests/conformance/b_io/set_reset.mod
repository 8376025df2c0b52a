MODULE MainModule
  ! Tests: Set makes a digital output 1 and Reset makes it 0 (read back with DOutput).
  VAR signaldo doLamp;
  PROC main()
    AliasIO "DO1", doLamp;
    TPWrite "initial=" \Num:=DOutput(doLamp);
    Set doLamp;
    TPWrite "after Set=" \Num:=DOutput(doLamp);
    Set doLamp;
    TPWrite "Set twice=" \Num:=DOutput(doLamp);
    Reset doLamp;
    TPWrite "after Reset=" \Num:=DOutput(doLamp);
  ENDPROC
ENDMODULE
