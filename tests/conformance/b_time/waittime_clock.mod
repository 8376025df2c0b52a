MODULE MainModule
  ! Tests: WaitTime lets (at least) the given time pass, as measured by a running clock.
  PROC main()
    VAR clock c;
    VAR num t;
    ClkReset c;
    ClkStart c;
    WaitTime 2;
    ClkStop c;
    t := ClkRead(c);
    TPWrite "at least 2 s=" \Bool:=t >= 2;
    TPWrite "below 3 s=" \Bool:=t < 3;
  ENDPROC
ENDMODULE
