MODULE TpReadFK
    ! The operator picks a function key; key 3 or higher stops the cell.
    VAR num key := 0;
    VAR bool running := TRUE;

    PROC main()
        WHILE running DO
            TPReadFK key, "Next?", "Go", "Go", "Stop", stEmpty, stEmpty;
            running := key < 3;
        ENDWHILE
    ENDPROC
ENDMODULE
