MODULE MainModule
  ! Tests: ClkStop freezes the clock: time passing afterwards does not change ClkRead.
  PROC main()
    VAR clock c;
    VAR num t1;
    VAR num t2;
    ClkReset c;
    ClkStart c;
    WaitTime 1;
    ClkStop c;
    t1 := ClkRead(c);
    WaitTime 3;
    t2 := ClkRead(c);
    TPWrite "unchanged=" \Bool:=t1 = t2;
    TPWrite "counted=" \Bool:=t1 >= 1 AND t1 < 2;
  ENDPROC
ENDMODULE
