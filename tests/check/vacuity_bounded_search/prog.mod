MODULE VacuityBoundedSearch
    ! x counts up to 50: more states than --max-states 5 lets the search store.
    VAR num x := 0;

    PROC main()
        WHILE x < 50 DO
            x := x + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
