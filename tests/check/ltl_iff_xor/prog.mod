MODULE LtlPhases
    ! phase goes 0, 1, 2, 3, then main ends.
    VAR num phase := 0;

    PROC main()
        phase := 1;
        phase := 2;
        phase := 3;
    ENDPROC
ENDMODULE
