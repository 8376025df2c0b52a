MODULE MainModule
  ! Tests: PulseDO without \PLength gives a pulse of 0.2 s: low again after one second.
  VAR signaldo doPulse;
  PROC main()
    AliasIO "DO1", doPulse;
    PulseDO doPulse;
    WaitTime 1;
    TPWrite "after=" \Num:=DOutput(doPulse);
  ENDPROC
ENDMODULE
