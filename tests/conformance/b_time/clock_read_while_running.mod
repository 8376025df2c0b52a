MODULE MainModule
  ! Tests: ClkRead can read a running clock, and its value grows while it runs.
  PROC main()
    VAR clock c;
    VAR num t1;
    VAR num t2;
    ClkReset c;
    ClkStart c;
    WaitTime 1;
    t1 := ClkRead(c);
    WaitTime 1;
    t2 := ClkRead(c);
    TPWrite "first=" \Bool:=t1 >= 1;
    TPWrite "grows=" \Bool:=t2 >= t1 + 1;
  ENDPROC
ENDMODULE
