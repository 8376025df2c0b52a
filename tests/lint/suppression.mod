MODULE Suppression
  PROC main()
    VAR bool a := TRUE;
    a := a AND NOT a AND a;  ! rapidmc: ignore[RMC801]
    a := a AND NOT a AND a;  ! rapidmc: ignore
    ! rapidmc: ignore[not-chain]
    a := a AND NOT a AND a;
    a := a AND NOT a AND a;  ! rapidmc: ignore[RMC808]  ! expect: RMC801
    a := a AND NOT a AND a;  ! expect: RMC801
  ENDPROC
ENDMODULE
