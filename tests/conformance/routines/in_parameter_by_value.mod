MODULE in_parameter_by_value
  ! Tests: a parameter without mode is passed by value: the routine may
  ! change its copy, the caller's variable is unchanged (also for arrays
  ! and records).
  PROC change(num n, pos p, num arr{*})
    n := n + 100;
    p.x := 99;
    arr{1} := 77;
    TPWrite "inside n=" \Num:=n;
  ENDPROC
  PROC main()
    VAR num v := 1;
    VAR pos q := [1, 2, 3];
    VAR num a{2} := [5, 6];
    change v, q, a;
    TPWrite "v=" \Num:=v;
    TPWrite "q=" \Pos:=q;
    TPWrite "a{1}=" \Num:=a{1};
  ENDPROC
ENDMODULE
