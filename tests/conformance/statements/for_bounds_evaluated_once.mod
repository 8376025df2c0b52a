MODULE for_bounds_evaluated_once
  ! Tests: FROM, TO and STEP are evaluated once before the loop: changing the
  ! variable used as TO inside the body does not change the number of runs.
  PROC main()
    VAR num n := 3;
    VAR num runs := 0;
    FOR i FROM 1 TO n DO
      n := n + 1;
      runs := runs + 1;
    ENDFOR
    TPWrite "runs=" \Num:=runs;
    TPWrite "n=" \Num:=n;
  ENDPROC
ENDMODULE
