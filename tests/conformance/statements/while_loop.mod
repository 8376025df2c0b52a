MODULE while_loop
  ! Tests: WHILE evaluates its condition before each iteration; a FALSE
  ! condition at entry runs the body zero times.
  PROC main()
    VAR num n := 1;
    WHILE n < 20 DO
      n := n * 3;
    ENDWHILE
    TPWrite "n=" \Num:=n;
    WHILE n < 0 DO
      TPWrite "never";
    ENDWHILE
    TPWrite "end";
  ENDPROC
ENDMODULE
