MODULE MainModule
  ! Tests: RETURN with a value inside a FOR loop of a function ends the loop and the function.
  VAR num calls := 0;
  PROC main()
    VAR num data{5} := [4, 8, -3, 7, -1];
    TPWrite "first negative at " \Num:=FirstNegative(data);
    TPWrite "count=" \Num:=calls;
  ENDPROC

  FUNC num FirstNegative(num a{*})
    FOR i FROM 1 TO Dim(a, 1) DO
      Incr calls;
      IF a{i} < 0 RETURN i;
    ENDFOR
    RETURN 0;
  ENDFUNC
ENDMODULE
