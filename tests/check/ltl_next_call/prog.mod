MODULE LtlNextCall
    ! A procedure call, its body and its return are steps of their own.
    VAR num phase := 0;

    PROC main()
        Bump;
        phase := 5;
    ENDPROC

    PROC Bump()
        phase := 1;
    ENDPROC
ENDMODULE
