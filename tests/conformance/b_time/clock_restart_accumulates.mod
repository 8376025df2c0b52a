MODULE MainModule
  ! Tests: ClkStart on a stopped clock continues counting from its value (no reset).
  PROC main()
    VAR clock c;
    VAR num t;
    ClkReset c;
    ClkStart c;
    WaitTime 1;
    ClkStop c;
    WaitTime 5;
    ClkStart c;
    WaitTime 1;
    ClkStop c;
    t := ClkRead(c);
    TPWrite "two intervals=" \Bool:=t >= 2 AND t < 3;
  ENDPROC
ENDMODULE
