MODULE handler_return_in_function
  ! Tests: RETURN with a value in a FUNC's ERROR handler makes that the
  ! function's result; the caller continues normally.
  FUNC num safeDiv(num a, num b)
    RETURN a / b;
  ERROR
    IF ERRNO = ERR_DIVZERO RETURN 0;
  ENDFUNC
  PROC main()
    TPWrite "6/3=" \Num:=safeDiv(6, 3);
    TPWrite "6/0=" \Num:=safeDiv(6, 0);
  ENDPROC
ENDMODULE
