MODULE VmErrNotIntVal
    ! DIV and MOD need integer operands.  Ten float32 tenths make 1.0000001,
    ! not 1: its MOD is ERR_NOTINTVAL, and nothing handles it.
    VAR num acc := 0;
    VAR num whole := 0;
    VAR num parity := -1;
    VAR num half := 0;

    PROC main()
        FOR i FROM 1 TO 10 DO
            acc := acc + 0.1;
        ENDFOR
        whole := Round(acc);
        half := 7 DIV 2;
        IF DInput(di_exact) = 1 THEN
            parity := whole MOD 2;
        ELSE
            parity := acc MOD 2;
        ENDIF
    ENDPROC
ENDMODULE
