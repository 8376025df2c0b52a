MODULE SealCell
  ! reg1..reg5 and clock1 come from the USER system module: used, never declared
  PROC main()
    TPReadFK reg1, "Dismiss the last cycle time?", stEmpty, stEmpty, stEmpty, "Yes", "No";
    IF reg1 = 4 TPErase;
    ClkReset clock1;
    ClkStart clock1;
    WaitTime 2;
    ClkStop clock1;
    reg2 := ClkRead(clock1);
    Incr reg3;
    TPWrite "cycle " \Num:=reg2;
    TPWrite "answer " \Num:=reg1;
    TPWrite "count " \Num:=reg3;
  ENDPROC
ENDMODULE
