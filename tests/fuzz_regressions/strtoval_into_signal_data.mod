! expect: exit 2 [RMC206]
! StrToVal writes a value; signal data holds a binding, not a value (once: the number
! written became a signal index and reading it was an internal TypeError).
MODULE StrToValSignal
  PROC main()
    VAR bool ok;
    VAR signalai nval;
    ok := StrToVal("3.85", nval);
    TPWrite "nval=" \Num:=nval;
  ENDPROC
ENDMODULE
