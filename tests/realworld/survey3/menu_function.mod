MODULE OperatorMenu
    ! A pendant menu written in a library module that was not given: it returns a record
    ! of that module and takes the button captions as an array of strings.
    PROC main()
        VAR choice picked;
        VAR string entries{2} := ["Run cycle", "Home"];
        VAR num rounds := 0;
        WHILE rounds < 2 DO
            picked := ShowMenu("Cell", entries, ["OK", "CANCEL"], \initial:=picked);
            IF picked.button = 2 RETURN;
            Incr rounds;
        ENDWHILE
    ENDPROC
ENDMODULE
