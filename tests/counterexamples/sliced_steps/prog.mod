MODULE SlicedSteps
    ! Steps the error does not depend on are told in one line; the steps it reads through a
    ! function (offset) and through a reference parameter (divisor) stay shown.
    VAR num waypoints{5};
    VAR num offset := 0;
    VAR num divisor := 1;

    FUNC num Shifted(num x)
        RETURN x - offset;
    ENDFUNC

    PROC Clear(VAR num d)
        d := 0;
    ENDPROC

    PROC main()
        waypoints{1} := 10;
        waypoints{2} := 20;
        offset := 5;
        waypoints{3} := 30;
        waypoints{4} := 40;
        TPWrite "cleared";
        Clear divisor;
        waypoints{5} := Shifted(7) / divisor;
    ENDPROC
ENDMODULE
