MODULE func_without_return_error
  ! Tests: a function that reaches ENDFUNC without RETURN raises
  ! ERR_FNCNORET (uncaught: exit 1).
  FUNC num maybe(num v)
    IF v > 0 RETURN v;
  ENDFUNC
  PROC main()
    TPWrite "pos=" \Num:=maybe(3);
    TPWrite "neg=" \Num:=maybe(-3);
  ENDPROC
ENDMODULE
