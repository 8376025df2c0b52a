MODULE trynext_inside_loop
  ! Tests: TRYNEXT continues with the statement after the failing one even
  ! inside a loop body; the loop then goes on with its next iteration.
  PROC main()
    VAR num x;
    FOR i FROM 0 TO 2 DO
      x := 6 / i;
      TPWrite "x=" \Num:=x;
    ENDFOR
    TPWrite "done";
  ERROR
    TRYNEXT;
  ENDPROC
ENDMODULE
