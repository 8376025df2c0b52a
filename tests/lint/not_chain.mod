MODULE NotChain
  PROC main()
    VAR bool a := TRUE;
    VAR bool b := FALSE;
    VAR bool c := TRUE;
    VAR num n := 1;
    a := a AND NOT b AND c;  ! expect: RMC801
    a := NOT a OR b;  ! expect: RMC801
    a := NOT b XOR c;  ! expect: RMC801
    a := NOT (a AND b);
    a := a AND (NOT b) AND c;
    a := NOT a;
    a := NOT n = 1;
    a := c AND NOT
      (a OR b);
    a := c AND NOT  ! expect: RMC801
      a OR b;
  ENDPROC
ENDMODULE
