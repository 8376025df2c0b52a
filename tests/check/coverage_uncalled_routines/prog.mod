MODULE CoverageUncalledRoutines
    ! Scale and Clamp take parameters and nothing calls them (a library module's unused
    ! helpers): dead code under any input, one warning naming both, each a place of it.
    ! Twice is called and runs.
    VAR num count := 0;

    PROC main()
        WHILE count < 3 DO
            count := Twice(count) + 1;
        ENDWHILE
    ENDPROC

    FUNC num Twice(num x)
        RETURN 2 * x;
    ENDFUNC

    FUNC num Scale(num x, num factor)
        RETURN x * factor;
    ENDFUNC

    PROC Clamp(INOUT num x)
        IF x > 10 x := 10;
    ENDPROC
ENDMODULE
