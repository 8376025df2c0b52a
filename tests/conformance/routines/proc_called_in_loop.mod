MODULE proc_called_in_loop
  ! Tests: a procedure called repeatedly from a loop gets fresh arguments on
  ! every call and can change caller data through an INOUT parameter.
  PROC accumulate(INOUT num sum, num v)
    sum := sum + v;
  ENDPROC
  PROC main()
    VAR num total := 0;
    FOR k FROM 1 TO 4 DO
      accumulate total, k * k;
    ENDFOR
    TPWrite "total=" \Num:=total;
  ENDPROC
ENDMODULE
