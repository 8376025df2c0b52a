MODULE InterruptInput
    ! A signal an interrupt watches is chosen at every step; it shows where it is chosen
    ! (and where a statement names it), not on every step.  count is assigned twice: the
    ! first value is overwritten before the failing line reads it.
    VAR intnum part_irq;
    VAR num count := 0;
    VAR num total := 0;

    PROC main()
        CONNECT part_irq WITH OnPart;
        ISignalDI di_part, 1, part_irq;
        count := 1;
        total := 2;
        count := 3;
        total := 10 / (count - 3);
    ENDPROC

    TRAP OnPart
        total := total + 1;
    ENDTRAP
ENDMODULE
